// `set` as the model does it for every front end: values put in dependency order and each
// checked against what the drive will hold before it, refusals with nothing sent, and a
// cancel that sends nothing more.
#include "model/session/SettingsWrite.h"
#include "tests/model/DriveSimFixture.h"

#include <QRegularExpression>

using namespace opentop;

namespace {

class SettingsWriteTest : public test::DriveSimFixture
{
protected:
    SettingsWrite::Plan prepare(SettingsWrite& set)
    {
        return await<SettingsWrite::Plan>([&](auto done) { set.prepare(done); });
    }
    bool write(SettingsWrite& set)
    {
        return await<bool>([&](auto done) { set.write([done] { done(true); }); });
    }
    int simValue(quint16 address)
    {
        const QString text =
            bus->control(1, {QStringLiteral("get"), QString::number(address)}).text;
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("= (\\d+) ")).match(text);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }
    int writesSent() const { return framesSent(6) + framesSent(16); }
    QStringList namesOf(const SettingsWrite& set) const
    {
        QStringList names;
        for (const SettingsWrite::Item& i : set.items())
            names << i.name;
        return names;
    }
};

} // namespace

TEST_F(SettingsWriteTest, TheModeIsWrittenBeforeTheFunctionsThatAreCheckedAgainstIt)
{
    startBus(QStringLiteral("dbu200@1"));
    ASSERT_EQ(simValue(0x2015), 1); // Mode2
    SettingsWrite set(session(1), false);
    // Given functions first: valid only in Mode1, which is given last.
    ASSERT_TRUE(set.add(QStringLiteral("io.x0"), QStringLiteral("RUN/STOP")).isEmpty());
    ASSERT_TRUE(set.add(QStringLiteral("io.x1"), QStringLiteral("CW/CCW")).isEmpty());
    ASSERT_TRUE(set.add(QStringLiteral("io.x2"), QStringLiteral("Not functioning")).isEmpty());
    ASSERT_TRUE(set.add(QStringLiteral("io.x3"), QStringLiteral("Not functioning")).isEmpty());
    ASSERT_TRUE(set.add(QStringLiteral("core.control_mode"), QStringLiteral("Mode1")).isEmpty());
    const SettingsWrite::Plan plan = prepare(set);
    ASSERT_EQ(plan.refusal, SettingsWrite::Refusal::None)
        << qPrintable(plan.problems.join(QLatin1Char('\n')));
    EXPECT_EQ(namesOf(set).first(), QStringLiteral("core.control_mode"));
    ASSERT_TRUE(write(set));
    for (const SettingsWrite::Item& i : set.items()) {
        EXPECT_TRUE(i.outcome.ok) << qPrintable(i.name) << ": " << qPrintable(i.outcome.error);
        EXPECT_TRUE(i.outcome.verified) << qPrintable(i.name);
    }
    EXPECT_EQ(simValue(0x2015), 0);
    EXPECT_EQ(simValue(0x2101), 1); // RUN/STOP in Mode1's codes
    EXPECT_EQ(simValue(0x2103), 2);
}

TEST_F(SettingsWriteTest, AModeThatWouldLeaveOtherFunctionsInvalidIsRefusedWithNothingSent)
{
    startBus(QStringLiteral("dbu200@1"));
    SettingsWrite set(session(1), false);
    set.add(QStringLiteral("core.control_mode"), QStringLiteral("Mode1"));
    set.add(QStringLiteral("io.x0"), QStringLiteral("RUN/STOP"));
    const int before = writesSent();
    const SettingsWrite::Plan plan = prepare(set);
    EXPECT_EQ(plan.refusal, SettingsWrite::Refusal::Invalid);
    ASSERT_FALSE(plan.problems.isEmpty());
    EXPECT_TRUE(plan.problems.join(QLatin1Char(' ')).contains(QStringLiteral("Input X1 function")))
        << qPrintable(plan.problems.join(QLatin1Char('\n')));
    ASSERT_TRUE(write(set)); // refused by prepare(): write() sends nothing
    EXPECT_EQ(writesSent(), before);
    EXPECT_EQ(simValue(0x2015), 1);
}

TEST_F(SettingsWriteTest, AValueOutsideItsRangeNamesTheAllowedRange)
{
    startBus(QStringLiteral("dbu400@1"));
    SettingsWrite set(session(1), false);
    set.add(QStringLiteral("spno5.speed"), QStringLiteral("280"));
    const SettingsWrite::Plan plan = prepare(set);
    EXPECT_EQ(plan.refusal, SettingsWrite::Refusal::Invalid);
    ASSERT_EQ(plan.problems.size(), 1);
    EXPECT_TRUE(plan.problems.first().contains(QStringLiteral("300")))
        << qPrintable(plan.problems.first());
    EXPECT_TRUE(plan.problems.first().contains(QStringLiteral("r/min")));
}

TEST_F(SettingsWriteTest, NamesCommandsAndRepeatsAreRefusedBeforeAnythingIsRead)
{
    startBus(QStringLiteral("dbu200@1"));
    SettingsWrite set(session(1), false);
    ASSERT_TRUE(set.add(QStringLiteral("spno2.speed"), QStringLiteral("1000")).isEmpty());
    const QString twice = set.add(QStringLiteral("spno2.speed"), QStringLiteral("1200"));
    EXPECT_TRUE(twice.contains(QStringLiteral("spno2.speed=1000"))) << qPrintable(twice);
    EXPECT_TRUE(twice.contains(QStringLiteral("spno2.speed=1200"))) << qPrintable(twice);
    set.add(QStringLiteral("no.such"), QStringLiteral("1"));
    set.add(QStringLiteral("status.speed"), QStringLiteral("1"));
    const int framesBefore = framesSent();
    const SettingsWrite::Plan plan = prepare(set);
    EXPECT_EQ(plan.refusal, SettingsWrite::Refusal::Invalid);
    const QString all = plan.problems.join(QLatin1Char('\n'));
    EXPECT_TRUE(all.contains(QStringLiteral("no parameter \"no.such\""))) << qPrintable(all);
    EXPECT_EQ(framesSent(), framesBefore); // nothing read, nothing written
}

TEST_F(SettingsWriteTest, ACancelSendsNothingMoreAndSaysWhatWasNotWritten)
{
    startBus(QStringLiteral("dbu200@1"));
    SettingsWrite set(session(1), false);
    for (int spno = 2; spno <= 8; ++spno)
        set.add(QStringLiteral("spno%1.speed").arg(spno), QString::number(1000 + spno));
    ASSERT_EQ(prepare(set).refusal, SettingsWrite::Refusal::None);
    const int before = writesSent();
    bool called = false;
    set.write([&called] { called = true; });
    set.cancel();                         // the first value is on its way
    waitUntil([] { return false; }, 500); // its answer arrives meanwhile
    EXPECT_FALSE(called);
    EXPECT_LE(writesSent() - before, 1) << "writes went on after the cancel";
    const QVector<SettingsWrite::Item>& items = set.items();
    // The one in flight may or may not be on the drive, and says so; the others were not sent.
    EXPECT_TRUE(items.first().outcome.unconfirmed);
    EXPECT_FALSE(items.first().outcome.ok);
    for (int k = 1; k < items.size(); ++k)
        EXPECT_TRUE(items[k].outcome.error.contains(QStringLiteral("not written")))
            << qPrintable(items[k].name) << ": " << qPrintable(items[k].outcome.error);
    EXPECT_NE(simValue(0xCA05), 1003); // SPno3 was never sent
    EXPECT_NE(simValue(0xCA0F), 1008); // nor SPno8
}
