#include "model/session/ParameterInitialiser.h"
#include "model/session/DeviceSession.h"
#include "sim/SimBus.h"
#include "tests/model/DriveSimFixture.h"

#include <gtest/gtest.h>

using namespace opentop;
using opentop::test::DriveSimFixture;

namespace {

class ParameterInitialiserTest : public DriveSimFixture
{
protected:
    void SetUp() override { startBus(QStringLiteral("dbu200@1,dcpid@7")); }

    int simGet(int slave, int address)
    {
        const QString text =
            bus->control(slave, {QStringLiteral("get"), QString::number(address)}).text;
        return text.section(QStringLiteral(" = "), 1).section(QLatin1Char(' '), 0, 0).toInt();
    }
};

} // namespace

TEST_F(ParameterInitialiserTest, SpellsOutTheConsequencesThenResetsEverySetting)
{
    session(1)->setLabelsInMessages(true);
    ParameterInitialiser init(session(1));
    ASSERT_TRUE(init.supported());
    control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("2200")});
    control(1, {QStringLiteral("set"), QStringLiteral("0x1021"), QStringLiteral("4")}); // 38400
    control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    const int writesBefore = framesSent(6);
    const auto plan = await<ParameterInitialiser::Plan>([&](auto done) { init.check(done); });
    EXPECT_TRUE(plan.refusal.isEmpty()) << qPrintable(plan.refusal);
    const QString all = plan.consequences.join(QLatin1Char('\n'));
    EXPECT_TRUE(all.contains(QStringLiteral("Every setting of drive 1 returns to its factory "
                                            "default")))
        << qPrintable(all);
    EXPECT_TRUE(all.contains(QStringLiteral("Running data"))) << qPrintable(all);
    EXPECT_TRUE(all.contains(
        QStringLiteral("Communication rate goes from 38400 bit/s (4) back to 19200 bit/s (2)")))
        << qPrintable(all);
    EXPECT_TRUE(all.contains(QStringLiteral("The link to the drive is lost from its next power-up: "
                                            "it answers only at the factory line settings, "
                                            "19200 bit/s, parity N, 1 stop bit(s).")))
        << qPrintable(all);
    EXPECT_TRUE(all.contains(QStringLiteral("Bus control is lost"))) << qPrintable(all);
    // Afterwards: reconnect at the profile's serial defaults, after its power-on delay, and
    // take bus control back.
    EXPECT_EQ(plan.reconnectBaud, 19200);
    EXPECT_EQ(plan.reconnectParity, 'N');
    EXPECT_EQ(plan.reconnectStopBits, 1);
    EXPECT_EQ(plan.powerOnDelayMs, 1000);
    EXPECT_TRUE(plan.busControlLost);
    const QString after = plan.afterwards.join(QLatin1Char('\n'));
    EXPECT_TRUE(after.contains(QStringLiteral("switch it off and on, wait 1 s after power-on, "
                                              "then reconnect at 19200 bit/s")))
        << qPrintable(after);
    EXPECT_TRUE(
        after.contains(QStringLiteral("set Control priority to Communication priority (2)")))
        << qPrintable(after);
    EXPECT_TRUE(all.contains(QStringLiteral("Control priority goes from"))) << qPrintable(all);
    EXPECT_TRUE(all.contains(QStringLiteral("Communication group stays"))) << qPrintable(all);
    EXPECT_TRUE(all.contains(QStringLiteral("The motor must stand still"))) << qPrintable(all);
    EXPECT_FALSE(all.contains(QStringLiteral("comm.rate"))) << qPrintable(all);
    EXPECT_TRUE(plan.command.startsWith(QStringLiteral("Parameter initialisation = ")))
        << qPrintable(plan.command);
    EXPECT_EQ(framesSent(6), writesBefore); // a check only reads

    const auto outcome = await<ParameterInitialiser::Outcome>([&](auto done) { init.run(done); });
    EXPECT_TRUE(outcome.ok) << qPrintable(outcome.error);
    EXPECT_EQ(simGet(1, 0xCA03), 1000);
    EXPECT_EQ(simGet(1, 0x1021), 2);
    EXPECT_EQ(simGet(1, 0x100D), 1);
}

// A drive already at the factory rate and in I/O priority keeps its link and loses no bus
// control: nothing to reconnect, nothing to take back.
TEST_F(ParameterInitialiserTest, NothingToReconnectWhenTheLineStaysTheSame)
{
    ParameterInitialiser init(session(1));
    control(1, {QStringLiteral("set"), QStringLiteral("0x1021"), QStringLiteral("2")}); // 19200
    control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("1")}); // I/O
    const auto plan = await<ParameterInitialiser::Plan>([&](auto done) { init.check(done); });
    EXPECT_TRUE(plan.refusal.isEmpty()) << qPrintable(plan.refusal);
    EXPECT_EQ(plan.reconnectBaud, 0);
    EXPECT_FALSE(plan.busControlLost);
    EXPECT_TRUE(plan.afterwards.isEmpty()) << qPrintable(plan.afterwards.join(QLatin1Char('\n')));
    EXPECT_FALSE(plan.consequences.join(QLatin1Char('\n')).contains(QStringLiteral("is lost")));
}

TEST_F(ParameterInitialiserTest, IsRefusedWhileTheMotorRunsAndNothingIsSent)
{
    ParameterInitialiser init(session(1));
    control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("2200")});
    // Running CCW in I/O priority: X1 = CCW/STOP.
    control(1, {QStringLiteral("input"), QStringLiteral("2")});
    ASSERT_TRUE(waitUntil([&] { return simGet(1, 0x0109) > 0; }));
    const int writesBefore = framesSent(6);
    const auto outcome = await<ParameterInitialiser::Outcome>([&](auto done) { init.run(done); });
    EXPECT_FALSE(outcome.ok);
    EXPECT_FALSE(outcome.sent);
    EXPECT_TRUE(outcome.error.contains(QStringLiteral("running"))) << qPrintable(outcome.error);
    EXPECT_EQ(framesSent(6), writesBefore);
    EXPECT_EQ(simGet(1, 0xCA03), 2200);
}

TEST_F(ParameterInitialiserTest, AProfileWithoutTheRoleHasNone)
{
    EXPECT_FALSE(ParameterInitialiser(session(7)).supported());
}
