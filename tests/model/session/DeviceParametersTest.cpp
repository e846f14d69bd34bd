#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "sim/FaultInjector.h"
#include "sim/SimBus.h"
#include "tests/model/DriveSimFixture.h"
#include "transport/ModbusClient.h"

#include <QEventLoop>
#include <QTimer>
#include <gtest/gtest.h>

using namespace opentop;
using opentop::test::DriveSimFixture;

namespace {

class DeviceParametersTest : public DriveSimFixture
{
protected:
    void SetUp() override { startBus(QStringLiteral("dbu200@1,dbu400@150")); }

    int wait(const std::function<void(std::function<void(int)>)>& start)
    {
        int failed = -1;
        QEventLoop loop;
        start([&](int f) {
            failed = f;
            loop.quit();
        });
        QTimer::singleShot(5000, &loop, &QEventLoop::quit);
        if (failed < 0)
            loop.exec();
        return failed;
    }
    int simGet(int slave, int address)
    {
        const QString text =
            bus->control(slave, {QStringLiteral("get"), QString::number(address)}).text;
        return text.section(QStringLiteral(" = "), 1).section(QLatin1Char(' '), 0, 0).toInt();
    }
};

} // namespace

TEST_F(DeviceParametersTest, PendingEditSurvivesABackgroundRefresh)
{
    DeviceSession& s = *session(1);
    DeviceParameters params(&s);
    ASSERT_EQ(wait([&](auto done) { params.refresh({}, done); }), 0);
    EXPECT_EQ(params.deviceText(QStringLiteral("spno2.speed")), QStringLiteral("1000 r/min"));
    EXPECT_TRUE(params.setPending(QStringLiteral("spno2.speed"), QStringLiteral("1800")).isEmpty());
    // The drive changes underneath (another tool); a refresh shows it but keeps the edit.
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("1200")});
    ASSERT_EQ(wait([&](auto done) { params.refresh({QStringLiteral("spno2.speed")}, done); }), 0);
    const DeviceParameters::Entry* e = params.entry(QStringLiteral("spno2.speed"));
    EXPECT_EQ(params.deviceText(QStringLiteral("spno2.speed")), QStringLiteral("1200 r/min"));
    EXPECT_EQ(e->state, DeviceParameters::State::Pending);
    EXPECT_EQ(e->pendingText, QStringLiteral("1800"));
    EXPECT_EQ(simGet(1, 0xCA03), 1200); // nothing written back
    EXPECT_EQ(wait([&](auto done) { params.write({}, done); }), 0);
    EXPECT_EQ(simGet(1, 0xCA03), 1800);
    EXPECT_EQ(e->state, DeviceParameters::State::Clean);
    EXPECT_FALSE(params.hasPending());
}

TEST_F(DeviceParametersTest, InvalidEditsAreRefusedAndCommandsAreNoEdits)
{
    DeviceParameters params(session(150));
    const QString error = params.setPending(QStringLiteral("spno2.speed"), QStringLiteral("280"));
    EXPECT_TRUE(error.contains(QStringLiteral("0 or 300–3000 r/min"))) << qPrintable(error);
    // A refused text is kept as an invalid edit (to correct or revert), never written.
    EXPECT_EQ(params.entry(QStringLiteral("spno2.speed"))->state, DeviceParameters::State::Invalid);
    EXPECT_EQ(params.invalidNames(), QStringList{QStringLiteral("spno2.speed")});
    params.revert(QStringLiteral("spno2.speed"));
    EXPECT_FALSE(params.hasPending());
    EXPECT_FALSE(params.setPending(QStringLiteral("run.start"), QStringLiteral("START")).isEmpty());
    EXPECT_FALSE(params.setPending(QStringLiteral("status.load"), QStringLiteral("5")).isEmpty());
    EXPECT_FALSE(params.hasPending());
}

TEST_F(DeviceParametersTest, ModeChangeRevalidatesTerminalEditsAndIsWrittenFirst)
{
    DeviceParameters params(session(1));
    ASSERT_EQ(wait([&](auto done) { params.refresh({}, done); }), 0);
    EXPECT_FALSE(params.setPending(QStringLiteral("io.x0"), QStringLiteral("RUN/STOP")).isEmpty());
    ASSERT_TRUE(
        params.setPending(QStringLiteral("core.control_mode"), QStringLiteral("Mode1")).isEmpty());
    ASSERT_TRUE(params.setPending(QStringLiteral("io.x0"), QStringLiteral("RUN/STOP")).isEmpty());
    EXPECT_EQ(params.pendingNames().size(), 2);
    // X1–X3 still hold Mode2 functions: the mode alone would leave them invalid, so nothing of
    // it is written (the model's rule; the I/O page offers the new mode's functions).
    EXPECT_GE(wait([&](auto done) { params.write({}, done); }), 1);
    EXPECT_EQ(simGet(1, 0x2015), 1);
    EXPECT_TRUE(params.entry(QStringLiteral("core.control_mode"))
                    ->message.contains(QStringLiteral("Input X1 function")))
        << qPrintable(params.entry(QStringLiteral("core.control_mode"))->message);
    ASSERT_TRUE(
        params.setPending(QStringLiteral("core.control_mode"), QStringLiteral("Mode1")).isEmpty());
    ASSERT_TRUE(params.setPending(QStringLiteral("io.x0"), QStringLiteral("RUN/STOP")).isEmpty());
    ASSERT_TRUE(params.setPending(QStringLiteral("io.x1"), QStringLiteral("CW/CCW")).isEmpty());
    ASSERT_TRUE(params.setPending(QStringLiteral("io.x2"), QStringLiteral("M0")).isEmpty());
    ASSERT_TRUE(params.setPending(QStringLiteral("io.x3"), QStringLiteral("M1")).isEmpty());
    EXPECT_EQ(wait([&](auto done) { params.write({}, done); }), 0);
    EXPECT_EQ(simGet(1, 0x2015), 0);
    EXPECT_EQ(simGet(1, 0x2101), 1);
    EXPECT_EQ(simGet(1, 0x2103), 2);
    // Switching back to Mode2 makes a pending Mode1 function invalid: it is flagged.
    ASSERT_TRUE(params.setPending(QStringLiteral("io.x1"), QStringLiteral("RUN/STOP")).isEmpty());
    ASSERT_TRUE(
        params.setPending(QStringLiteral("core.control_mode"), QStringLiteral("Mode2")).isEmpty());
    EXPECT_FALSE(params.entry(QStringLiteral("io.x1"))->message.isEmpty());
    EXPECT_EQ(params.entry(QStringLiteral("io.x1"))->state, DeviceParameters::State::Invalid);
}

TEST_F(DeviceParametersTest, AWriteWithAnInvalidEditSendsNothingAndSaysWhichByLabel)
{
    session(1)->setLabelsInMessages(true); // as the program's windows do
    DeviceParameters params(session(1));
    ASSERT_EQ(wait([&](auto done) { params.refresh({}, done); }), 0);
    const int accelBefore = simGet(1, 0x1303);
    ASSERT_TRUE(params.setPending(QStringLiteral("spno2.accel"), QStringLiteral("7.5")).isEmpty());
    const QString error = params.setPending(QStringLiteral("spno2.speed"), QStringLiteral("5000"));
    EXPECT_TRUE(error.startsWith(QStringLiteral("SPno2 speed: "))) << qPrintable(error);
    EXPECT_EQ(params.problemText(QStringLiteral("spno2.speed")),
              QStringLiteral("5000 r/min is not allowed; allowed: 0 or 250–3000 r/min"));
    const QStringList summary = params.invalidSummary();
    ASSERT_EQ(summary.size(), 1);
    EXPECT_TRUE(summary.first().startsWith(QStringLiteral("SPno2 speed: 5000 r/min")))
        << qPrintable(summary.first());
    // All or nothing: the valid edit is not written either.
    EXPECT_EQ(wait([&](auto done) { params.write({}, done); }), 1);
    EXPECT_EQ(simGet(1, 0x1303), accelBefore);
    EXPECT_EQ(params.entry(QStringLiteral("spno2.accel"))->state, DeviceParameters::State::Pending);
    // Corrected, both are written.
    ASSERT_TRUE(params.setPending(QStringLiteral("spno2.speed"), QStringLiteral("2000")).isEmpty());
    EXPECT_TRUE(params.invalidNames().isEmpty());
    EXPECT_EQ(wait([&](auto done) { params.write({}, done); }), 0);
    EXPECT_EQ(simGet(1, 0x1303), 75);
    EXPECT_EQ(simGet(1, 0xCA03), 2000);
}

TEST_F(DeviceParametersTest, AValueReadAfterAFailedReadIsNoLongerMarked)
{
    DeviceParameters params(session(1));
    bus->setFaults(FaultInjector(*FaultInjector::parse(QStringLiteral("drop=1"), nullptr)));
    EXPECT_GE(wait([&](auto done) { params.refresh({QStringLiteral("spno2.speed")}, done); }), 1);
    EXPECT_FALSE(params.entry(QStringLiteral("spno2.speed"))->message.isEmpty());
    bus->setFaults(FaultInjector());
    EXPECT_EQ(wait([&](auto done) { params.refresh({QStringLiteral("spno2.speed")}, done); }), 0);
    EXPECT_TRUE(params.entry(QStringLiteral("spno2.speed"))->message.isEmpty());
    EXPECT_EQ(params.entry(QStringLiteral("spno2.speed"))->state, DeviceParameters::State::Clean);
}

TEST_F(DeviceParametersTest, AFailedWriteIsShownAtTheField)
{
    DeviceParameters params(session(1));
    ASSERT_TRUE(params.setPending(QStringLiteral("spno2.accel"), QStringLiteral("2.5")).isEmpty());
    bus->setFaults(FaultInjector(*FaultInjector::parse(QStringLiteral("drop=1"), nullptr)));
    EXPECT_EQ(wait([&](auto done) { params.write({}, done); }), 1);
    const DeviceParameters::Entry* e = params.entry(QStringLiteral("spno2.accel"));
    EXPECT_EQ(e->state, DeviceParameters::State::Failed);
    EXPECT_FALSE(e->message.isEmpty());
    EXPECT_EQ(params.pendingNames(), QStringList{QStringLiteral("spno2.accel")}); // still to do
}
