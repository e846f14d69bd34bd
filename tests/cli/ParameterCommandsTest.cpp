#include "cli/ExitCode.h"
#include "tests/cli/CliTestSupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

const QString kSim = QStringLiteral("--sim=dbu200@1,dbu400@150,dcpid@7");

QJsonObject json(const CliRun& r)
{
    return QJsonDocument::fromJson(r.out.toUtf8()).object();
}

} // namespace

TEST(ParamsCommand, JsonListsEveryParameterWithItsMetadata)
{
    const CliRun r = runCli({QStringLiteral("params"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QJsonObject root = json(r);
    EXPECT_EQ(root.value(QStringLiteral("schema")).toInt(), 1);
    const QJsonArray families = root.value(QStringLiteral("families")).toArray();
    ASSERT_EQ(families.size(), 2);
    QJsonObject speed;
    for (const QJsonValue& p :
         families[0].toObject().value(QStringLiteral("parameters")).toArray()) {
        if (p.toObject().value(QStringLiteral("name")).toString() == QLatin1String("spno2.speed"))
            speed = p.toObject();
    }
    EXPECT_EQ(speed.value(QStringLiteral("address")).toInt(), 0xCA03);
    EXPECT_EQ(speed.value(QStringLiteral("readFunction")).toInt(), 3);
    EXPECT_EQ(speed.value(QStringLiteral("writeFunction")).toInt(), 6);
    EXPECT_EQ(speed.value(QStringLiteral("unit")).toString(), QStringLiteral("r/min"));
    EXPECT_EQ(speed.value(QStringLiteral("default")).toDouble(), 1000);
    EXPECT_EQ(speed.value(QStringLiteral("access")).toString(), QStringLiteral("rw"));
    EXPECT_TRUE(speed.value(QStringLiteral("allowedText"))
                    .toString()
                    .contains(QStringLiteral("dbu400: 0 or 300–3000 r/min")));
    EXPECT_EQ(speed.value(QStringLiteral("when")).toArray().size(), 1);
}

TEST(ParamsCommand, HumanTableAndFamilyFilter)
{
    CliRun r =
        runCli({QStringLiteral("params"), QStringLiteral("--family"), QStringLiteral("dcpid")});
    ASSERT_EQ(r.code, ExitOk);
    EXPECT_TRUE(r.out.contains(QStringLiteral("config.comm_loss_time")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("spno2.speed")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("core.control_mode")) == false);
    r = runCli({QStringLiteral("params"), QStringLiteral("--family"), QStringLiteral("vfd")});
    EXPECT_EQ(r.code, ExitUsage);
}

TEST(GetCommand, ReadsByNameGroupAndRaw)
{
    CliRun r = runCli({QStringLiteral("get"), QStringLiteral("1"), QStringLiteral("spno2.speed"),
                       QStringLiteral("spno2.accel"), kSim});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("1000 r/min")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("0.5 s")));
    r = runCli({QStringLiteral("get"), QStringLiteral("7"), QStringLiteral("--group"),
                QStringLiteral("pid"), QStringLiteral("--json"), kSim});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_EQ(json(r).value(QStringLiteral("family")).toString(), QStringLiteral("dcpid"));
    EXPECT_GE(json(r).value(QStringLiteral("values")).toArray().size(), 4);
    r = runCli({QStringLiteral("get"), QStringLiteral("1"), QStringLiteral("--raw"),
                QStringLiteral("0xCA03"), kSim});
    ASSERT_EQ(r.code, ExitOk);
    EXPECT_TRUE(r.out.contains(QStringLiteral("03E8")));
    r = runCli({QStringLiteral("get"), QStringLiteral("1"), QStringLiteral("no.such"), kSim});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("no parameter \"no.such\"")));
    r = runCli({QStringLiteral("get"), QStringLiteral("42"), QStringLiteral("spno2.speed"),
                QStringLiteral("--timeout"), QStringLiteral("20"), kSim});
    EXPECT_EQ(r.code, ExitCommunication);
    EXPECT_TRUE(r.err.contains(QStringLiteral("machine number 42")));
}

TEST(SetCommand, WritesVerifiesAndRefusesInvalidValuesWithoutSending)
{
    CliRun r =
        runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.accel=2.5"),
                QStringLiteral("spno3.direction=CCW"), kSim});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_EQ(r.out.count(QStringLiteral("written, verified")), 2) << qPrintable(r.out);

    // One invalid value: nothing at all is sent (the valid one neither).
    r = runCli({QStringLiteral("set"), QStringLiteral("150"), QStringLiteral("spno2.accel=3"),
                QStringLiteral("spno2.speed=280"), kSim, QStringLiteral("--trace")});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("0 or 300–3000 r/min"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was written")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("written")));
}

TEST(SetCommand, DependentValuesAreCheckedAgainstTheNewMode)
{
    CliRun r = runCli(
        {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("io.x0=RUN/STOP"), kSim});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("only available when core.control_mode is 0")))
        << qPrintable(r.err);
    // The mode with only X0 would leave X1–X3 holding Mode2 functions: refused, named.
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("io.x0=RUN/STOP"),
                QStringLiteral("core.control_mode=Mode1"), kSim});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("Input X1 function (CCW/STOP)")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was written")));
    // Switching the mode with a Mode1 function for every input; the mode goes first.
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("io.x0=RUN/STOP"),
                QStringLiteral("io.x1=CW/CCW"), QStringLiteral("io.x2=M0"),
                QStringLiteral("io.x3=M1"), QStringLiteral("core.control_mode=Mode1"), kSim});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_LT(r.out.indexOf(QStringLiteral("core.control_mode")),
              r.out.indexOf(QStringLiteral("io.x0")));
}

TEST(SetCommand, CommandsAndRawWritesNeedConfirmation)
{
    CliRun r = runCli(
        {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("run.start=START"), kSim});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("add --yes")));
    // Confirmed, but the drive is in I/O priority: the drive's own refusal is explained.
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("run.start=START"),
                QStringLiteral("--yes"), kSim});
    EXPECT_EQ(r.code, ExitCommunication);
    EXPECT_TRUE(r.out.contains(QStringLiteral("E2h"))) << qPrintable(r.out);
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("--raw"),
                QStringLiteral("0xCA03=2000"), kSim});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("written, verified")));
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("--raw"),
                QStringLiteral("0xCA03=20"), kSim});
    EXPECT_EQ(r.code, ExitInvalid);
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("--raw"),
                QStringLiteral("0x5555=1"), kSim});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("not a register the profile knows")));
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("--raw"),
                QStringLiteral("0x2003=1"), kSim});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--yes")));
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed"), kSim});
    EXPECT_EQ(r.code, ExitUsage);
}

// Parameter initialisation (0x1025) resets the line settings and control priority too: the
// command line says what it changes before it needs --yes.
TEST(SetCommand, ParameterInitialisationSaysWhatItResetsFirst)
{
    CliRun r = runCli(
        {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("cmd.param_init=1"), kSim});
    EXPECT_EQ(r.code, ExitInvalid);
    const int warning = r.err.indexOf(
        QStringLiteral("warning: Every setting of drive 1 returns to its factory default"));
    EXPECT_GE(warning, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("warning: Communication rate stays 19200 bit/s")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("warning: Control priority stays I/O priority")))
        << qPrintable(r.err);
    EXPECT_GT(r.err.indexOf(QStringLiteral("add --yes")), warning) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was written")));
    // Confirmed: sent. The line and control priority stay as they are: nothing to do next.
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("cmd.param_init=1"),
                QStringLiteral("--yes"), kSim});
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("warning: Every setting of drive 1")))
        << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("next:"))) << qPrintable(r.err);
}

TEST(PortsCommand, ListsAndExplainsTypedPaths)
{
    const CliRun r = runCli({QStringLiteral("ports")});
    EXPECT_EQ(r.code, ExitOk);
    EXPECT_FALSE(r.out.isEmpty());
    EXPECT_EQ(runCli({QStringLiteral("ports"), QStringLiteral("--json")}).code, ExitOk);
    EXPECT_EQ(runCli({QStringLiteral("ports"), QStringLiteral("extra")}).code, ExitUsage);
}

TEST(SetCommand, WarnsOfAShortDecelerationFromHighSpeedButWrites)
{
    // SPno2 at 2500 r/min with a 0.5 s deceleration: advised against, still a valid setting.
    CliRun r =
        runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed=2500"),
                QStringLiteral("spno2.decel=0.5"), kSim});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(
        r.err.contains(QStringLiteral("warning: SPno2 slows down from 2500 r/min in 0.5 s")))
        << qPrintable(r.err);
    EXPECT_EQ(r.out.count(QStringLiteral("written, verified")), 2) << qPrintable(r.out);
    // The speed alone, with the drive's own deceleration read for the check.
    r = runCli(
        {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno3.speed=2000"), kSim});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("warning: SPno3"))) << qPrintable(r.err);
    // A slow speed, or 2 s and more: no warning.
    r = runCli({QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed=2500"),
                QStringLiteral("spno2.decel=3"), kSim});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("warning: SPno2"))) << qPrintable(r.err);
}
