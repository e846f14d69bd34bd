// The control-mode / input-function rule as every writer meets it in DeviceSession::write: a
// mode that would leave the drive's input functions invalid is refused before anything is sent,
// unless valid functions are written in the same operation.
#include "model/session/DependentValues.h"
#include "model/session/DeviceParameters.h"
#include "tests/model/DriveSimFixture.h"

#include <QRegularExpression>

using namespace opentop;

namespace {

class DependentValuesTest : public test::DriveSimFixture
{
protected:
    DeviceSession::Outcome write(const QString& name, const QString& text,
                                 const QStringList& companions = {})
    {
        DeviceSession::WriteOptions options;
        options.companions = companions;
        return await<DeviceSession::Outcome>(
            [&](auto done) { session(1)->write(name, text, options, done); });
    }
    int simValue(quint16 address)
    {
        const QString text =
            bus->control(1, {QStringLiteral("get"), QString::number(address)}).text;
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("= (\\d+) ")).match(text);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }
};

} // namespace

TEST_F(DependentValuesTest, TheDependentsOfTheControlModeAreTheInputFunctions)
{
    const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    EXPECT_EQ(DependentValues::of(dbu, *dbu.parameter(QStringLiteral("core.control_mode"))),
              QStringList({QStringLiteral("io.x0"), QStringLiteral("io.x1"),
                           QStringLiteral("io.x2"), QStringLiteral("io.x3")}));
    EXPECT_TRUE(DependentValues::of(dbu, *dbu.parameter(QStringLiteral("spno2.speed"))).isEmpty());
}

TEST_F(DependentValuesTest, AModeThatLeavesTheInputFunctionsInvalidIsRefusedBeforeSending)
{
    startBus(QStringLiteral("dbu200@1"));
    ASSERT_EQ(simValue(0x2015), 1); // Mode2, with Mode2 input functions
    const int writesBefore = framesSent(6) + framesSent(16);
    const DeviceSession::Outcome o =
        write(QStringLiteral("core.control_mode"), QStringLiteral("Mode1"));
    EXPECT_FALSE(o.ok);
    EXPECT_FALSE(o.sent);
    EXPECT_EQ(framesSent(6) + framesSent(16), writesBefore);
    EXPECT_EQ(simValue(0x2015), 1);
    // In words, naming the settings by their labels and the values they hold.
    EXPECT_TRUE(o.error.contains(QStringLiteral("Control mode = Mode1"))) << qPrintable(o.error);
    EXPECT_TRUE(o.error.contains(QStringLiteral("Input X0 function (CW/STOP)")))
        << qPrintable(o.error);
    EXPECT_FALSE(o.error.contains(QStringLiteral("io.x0"))) << qPrintable(o.error);
}

TEST_F(DependentValuesTest, TheModeGoesThroughWithValidFunctionsWrittenInTheSameOperation)
{
    startBus(QStringLiteral("dbu200@1"));
    const QStringList inputs = {QStringLiteral("io.x0"), QStringLiteral("io.x1"),
                                QStringLiteral("io.x2"), QStringLiteral("io.x3")};
    const DeviceSession::Outcome mode =
        write(QStringLiteral("core.control_mode"), QStringLiteral("Mode1"), inputs);
    ASSERT_TRUE(mode.ok) << qPrintable(mode.error);
    EXPECT_EQ(simValue(0x2015), 0);
    // Each function is then checked against Mode1.
    EXPECT_FALSE(write(QStringLiteral("io.x0"), QStringLiteral("CW/STOP")).ok);
    EXPECT_TRUE(write(QStringLiteral("io.x0"), QStringLiteral("RUN/STOP"), inputs.mid(1)).ok);
}

TEST_F(DependentValuesTest, APageWriteOfTheModeAloneFailsAtTheFieldAndWritesNothing)
{
    startBus(QStringLiteral("dbu200@1"));
    DeviceParameters parameters(session(1));
    await<DeviceSession::ReadManyOutcome>(
        [&](auto done) { session(1)->readMany({QStringLiteral("core.control_mode")}, done); });
    ASSERT_TRUE(parameters.setPending(QStringLiteral("core.control_mode"), QStringLiteral("Mode1"))
                    .isEmpty());
    const int failed = await<int>([&](auto done) { parameters.write({}, done); });
    EXPECT_EQ(failed, 1);
    EXPECT_EQ(simValue(0x2015), 1);
    EXPECT_TRUE(parameters.entry(QStringLiteral("core.control_mode"))
                    ->message.contains(QStringLiteral("Input X0 function")));
}

// The DC controller's speed command follows its speed mode but is a write-only command: it holds
// no value a mode change could leave invalid, so changing the mode is not refused for want of
// reading it.
TEST_F(DependentValuesTest, AWriteOnlyCommandDoesNotBlockItsControllingSetting)
{
    const Profile& dc = *ProfileRegistry::builtIn().family(QStringLiteral("dcpid"));
    const ParameterMeta* mode = dc.parameter(QStringLiteral("config.speed_mode"));
    ASSERT_TRUE(mode);
    ASSERT_TRUE(dc.parameter(QStringLiteral("speed.command"))
                    ->controllingParameters()
                    .contains(mode->name));
    EXPECT_FALSE(DependentValues::of(dc, *mode).contains(QStringLiteral("speed.command")));
    startBus(QStringLiteral("dcpid@1"));
    const DeviceSession::Outcome o =
        write(QStringLiteral("config.speed_mode"), QStringLiteral("Speed loop (commutation)"));
    EXPECT_TRUE(o.ok) << qPrintable(o.error);
    EXPECT_TRUE(o.verified);
}
