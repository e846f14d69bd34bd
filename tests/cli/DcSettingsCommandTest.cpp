// `set` and `scan` for the DC controller's manual rules (issue 14 §3): PID coefficients above
// the recommendation written with a warning, the serial lock only with --yes, the line settings'
// note, and the fixed potentiometer-mode settings offered after an empty scan.
#include "cli/ExitCode.h"
#include "tests/cli/CliTestSupport.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

const QString kSim = QStringLiteral("--sim=dcpid@7");

CliRun set(const QStringList& args)
{
    return runCli(QStringList{kSim, QStringLiteral("set"), QStringLiteral("7")} + args);
}

} // namespace

TEST(DcSettingsCommand, PidAboveTheRecommendationIsWrittenWithAWarning)
{
    CliRun r = set({QStringLiteral("pid.p=2.5")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("written, verified"))) << qPrintable(r.out);
    EXPECT_TRUE(r.err.contains(QStringLiteral("warning: pid.p: 2.5000 is outside the recommended "
                                              "range 0.0000–1.0000")))
        << qPrintable(r.err);

    r = set({QStringLiteral("pid.p=0.5")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("warning"))) << qPrintable(r.err);

    r = set({QStringLiteral("pid.i=100.5")});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("allowed: 0.0000–100.0000"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was written"))) << qPrintable(r.err);
}

TEST(DcSettingsCommand, PidWarningIsInTheJson)
{
    const CliRun r = set({QStringLiteral("pid.d=3"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("\"warning\": \"pid.d: 3.0000 is outside")))
        << qPrintable(r.out);
}

TEST(DcSettingsCommand, TheSerialLockIsRefusedWithoutYesAndSaysHowToUndoIt)
{
    CliRun r = set({QStringLiteral("config.serial_lock=Disabled")});
    EXPECT_EQ(r.code, ExitInvalid);
    for (const char* part :
         {"prohibits configuration over the serial interface", "switch the drive off and on",
          "9600 bit/s, 8E1, address 1", "Add --yes to set it.", "nothing was written"})
        EXPECT_TRUE(r.err.contains(QString::fromUtf8(part))) << part << "\n" << qPrintable(r.err);
    EXPECT_FALSE(r.out.contains(QStringLiteral("written"))) << qPrintable(r.out);

    r = set({QStringLiteral("config.serial_lock=Disabled"), QStringLiteral("--yes")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("written, verified"))) << qPrintable(r.out);
    EXPECT_TRUE(r.err.contains(QStringLiteral("warning: config.serial_lock = Disabled (1)")))
        << qPrintable(r.err);

    // Lifting it needs no confirmation.
    r = set({QStringLiteral("config.serial_lock=Allowed")});
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
}

TEST(DcSettingsCommand, ALineSettingSaysItIsUsedFromTheNextPowerUp)
{
    const CliRun r = set({QStringLiteral("config.baud=19200")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("note: the drive uses config.baud from its next "
                                              "power-up on")))
        << qPrintable(r.err);
}

TEST(DcSettingsCommand, AnEmptyScanOffersTheFixedPotentiometerModeSettings)
{
    // Nobody at 2–3: the DC controller at 1 is outside the range.
    CliRun r = runCli({QStringLiteral("--sim=dcpid@1"), QStringLiteral("--baud"),
                       QStringLiteral("19200"), QStringLiteral("scan"), QStringLiteral("--wait"),
                       QStringLiteral("10"), QStringLiteral("--from"), QStringLiteral("2"),
                       QStringLiteral("--to"), QStringLiteral("3")});
    EXPECT_EQ(r.code, ExitCommunication);
    const QString hint = QStringLiteral(
        "hint: A DC controller in potentiometer/analog control mode talks only at 9600 bit/s, "
        "8E1, address 1. Retry with the same connection and: --baud 9600 --parity E "
        "--stop-bits 1 scan --from 1 --to 1");
    EXPECT_TRUE(r.err.contains(hint)) << qPrintable(r.err);

    // Already at those settings and address: no potentiometer-mode retry to offer (the
    // other-format hint for a DBU may still be there).
    r = runCli({QStringLiteral("--sim=dcpid@5"), QStringLiteral("--baud"), QStringLiteral("9600"),
                QStringLiteral("--parity"), QStringLiteral("E"), QStringLiteral("scan"),
                QStringLiteral("--wait"), QStringLiteral("10"), QStringLiteral("--from"),
                QStringLiteral("1"), QStringLiteral("--to"), QStringLiteral("2")});
    EXPECT_EQ(r.code, ExitCommunication);
    EXPECT_FALSE(r.err.contains(QStringLiteral("potentiometer"))) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("about 0 s"))) << qPrintable(r.err);
}
