// Alarm and warning records, the communication error register, alarm reset and erasing,
// against the in-process simulated DBU.
#include "model/alarms/AlarmHistory.h"
#include "tests/model/DriveSimFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class AlarmHistoryTest : public DriveSimFixture
{
protected:
    void SetUp() override { startBus(QStringLiteral("dbu200@1,dcpid@7")); }

    AlarmHistory::Report read(AlarmHistory& history)
    {
        return await<AlarmHistory::Report>([&](auto done) { history.read(done); });
    }
    AlarmHistory::ResetOutcome reset(AlarmHistory& history)
    {
        return await<AlarmHistory::ResetOutcome>([&](auto done) { history.reset(done); });
    }
};

} // namespace

TEST_F(AlarmHistoryTest, AlarmAppearsNewestFirstWithItsRemedy)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("3")});
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    control(1, {QStringLiteral("warning"), QStringLiteral("0x17")});
    AlarmHistory history(session(1));
    ASSERT_TRUE(history.supported());
    const AlarmHistory::Report report = read(history);
    ASSERT_TRUE(report.ok) << qPrintable(report.errors.join(QLatin1Char('\n')));
    // 15 + 15 records in two blocks each (17 registers at most), the error register, status,
    // the alarm erase method.
    EXPECT_EQ(report.requests, 7);
    EXPECT_FALSE(report.powerRestartOnly);
    EXPECT_EQ(report.eraseMethod, QStringLiteral("core.alarm_erase = Alarm-Reset"));
    ASSERT_EQ(report.histories.size(), 2);
    const AlarmHistory::History& alarms = report.histories[0];
    EXPECT_EQ(alarms.table, QStringLiteral("alarm"));
    ASSERT_EQ(alarms.records.size(), 15);
    EXPECT_EQ(alarms.used(), 2);
    EXPECT_EQ(alarms.records[0].code, 7);
    ASSERT_TRUE(alarms.records[0].entry);
    EXPECT_EQ(alarms.records[0].entry->panel, QStringLiteral("AL007"));
    EXPECT_EQ(alarms.records[0].entry->name, QStringLiteral("Overload"));
    EXPECT_FALSE(alarms.records[0].entry->remedy.isEmpty());
    EXPECT_EQ(alarms.records[1].code, 3);
    EXPECT_TRUE(alarms.records[2].empty);
    EXPECT_EQ(alarms.distinctEntries().size(), 2);
    const AlarmHistory::History& warnings = report.histories[1];
    EXPECT_EQ(warnings.used(), 1);
    EXPECT_EQ(warnings.records[0].entry->panel, QStringLiteral("WR017"));
    EXPECT_EQ(report.alarmActive, std::optional<bool>(true));
    EXPECT_EQ(report.commErrorCode, std::optional<qint64>(0));
}

TEST_F(AlarmHistoryTest, CommunicationErrorRegisterIsDecoded)
{
    control(1, {QStringLiteral("set"), QStringLiteral("0x007B"), QStringLiteral("0xE2"),
                QStringLiteral("4")});
    AlarmHistory history(session(1));
    const AlarmHistory::Report report = read(history);
    EXPECT_EQ(report.commErrorParameter, QStringLiteral("status.comm_error"));
    ASSERT_TRUE(report.commError);
    EXPECT_EQ(report.commError->panel, QStringLiteral("E2h"));
    EXPECT_EQ(report.commError->name, QStringLiteral("Cannot execute command"));
}

TEST_F(AlarmHistoryTest, ResetClearsAnAlarmTheResetCommandClears)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    AlarmHistory history(session(1));
    EXPECT_TRUE(
        history.resetPlan().value(0).startsWith(QStringLiteral("cmd.alarm_reset = Reset (0)")))
        << qPrintable(history.resetPlan().value(0));
    const AlarmHistory::ResetOutcome o = reset(history);
    EXPECT_TRUE(o.sent);
    EXPECT_TRUE(o.ok) << qPrintable(o.error);
    EXPECT_TRUE(o.wasActive);
    EXPECT_EQ(o.stillActive, std::optional<bool>(false));
    EXPECT_FALSE(o.powerCycleNeeded);
    EXPECT_EQ(o.explanation, QStringLiteral("AL007 Overload is cleared."));
    // The record stays.
    EXPECT_EQ(read(history).histories[0].records[0].code, 7);
}

TEST_F(AlarmHistoryTest, ResetExplainsAnAlarmOnlyAPowerCycleClears)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("0x0B")});
    AlarmHistory history(session(1));
    const AlarmHistory::ResetOutcome o = reset(history);
    EXPECT_TRUE(o.sent);
    EXPECT_FALSE(o.ok); // the drive refuses: 04 / E2h
    EXPECT_EQ(o.stillActive, std::optional<bool>(true));
    EXPECT_TRUE(o.powerCycleNeeded);
    EXPECT_TRUE(o.explanation.startsWith(
        QStringLiteral("AL00B Hall signal error is still active: only a power cycle clears it.")))
        << qPrintable(o.explanation);
    control(1, {QStringLiteral("power-cycle")});
    EXPECT_EQ(read(history).alarmActive, std::optional<bool>(false));
}

TEST_F(AlarmHistoryTest, ResetExplainsADriveSetToClearByPowerRestart)
{
    control(1, {QStringLiteral("set"), QStringLiteral("0x1005"), QStringLiteral("0")});
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    AlarmHistory history(session(1));
    const AlarmHistory::ResetOutcome o = reset(history);
    EXPECT_EQ(o.stillActive, std::optional<bool>(true));
    EXPECT_TRUE(o.powerCycleNeeded);
    EXPECT_TRUE(o.explanation.contains(QStringLiteral("core.alarm_erase = Restart power")))
        << qPrintable(o.explanation);
    EXPECT_TRUE(read(history).powerRestartOnly);
}

TEST_F(AlarmHistoryTest, ResetWithoutAnAlarmSaysSo)
{
    AlarmHistory history(session(1));
    const AlarmHistory::ResetOutcome o = reset(history);
    EXPECT_FALSE(o.wasActive);
    EXPECT_EQ(o.stillActive, std::optional<bool>(false));
    EXPECT_EQ(o.explanation, QStringLiteral("No alarm was active; nothing to clear."));
}

TEST_F(AlarmHistoryTest, ClearRecordsErasesBothTablesAndReadsThemBack)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    control(1, {QStringLiteral("warning"), QStringLiteral("5")});
    AlarmHistory history(session(1));
    EXPECT_EQ(history.clearPlan().size(), 2);
    const AlarmHistory::ClearOutcome o =
        await<AlarmHistory::ClearOutcome>([&](auto done) { history.clearRecords(done); });
    EXPECT_TRUE(o.ok) << qPrintable(o.errors.join(QLatin1Char('\n')));
    EXPECT_EQ(o.cleared,
              (QStringList{QStringLiteral("Alarm codes"), QStringLiteral("Warning codes")}));
    EXPECT_EQ(o.erasedRecords, 2);
    EXPECT_TRUE(o.verified);
    const AlarmHistory::Report after = read(history);
    EXPECT_EQ(after.histories[0].used(), 0);
    EXPECT_EQ(after.histories[1].used(), 0);
}

TEST_F(AlarmHistoryTest, DcControllerKeepsNoRecords)
{
    AlarmHistory history(session(7));
    EXPECT_FALSE(history.supported());
    EXPECT_FALSE(history.canReset());
    EXPECT_FALSE(history.canClear());
}
