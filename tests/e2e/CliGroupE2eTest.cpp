// Communication groups through opentop-cli over a pty against opentop-sim: a write or command to
// a group parent also reaches its children (TROY manual 11-3), so the CLI names them, refuses
// without --yes (nothing sent), and with --yes reads back what the children hold; scan shows
// each drive's group and the setups that are wrong.
#include "model/bus/BusMemory.h"
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"
#include "transport/ConnectionSettings.h"

using namespace opentop;
using namespace opentop::test;

namespace {

const QString kBus = QStringLiteral("--bus-drives=1,3,5");

CliResult cli(const SimProcess& sim, const QStringList& args)
{
    return runCliOn(sim.pty, args);
}

// Drives 1, 3 and 5; 3 and 5 are children of 1.
void startGroupedBus(SimProcess* sim, const QString& devices)
{
    QString error;
    ASSERT_TRUE(sim->start({QStringLiteral("--devices"), devices}, &error)) << qPrintable(error);
    // A pty's name comes back for the next simulator: nothing remembered for it is this bus.
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Serial;
    settings.port = sim->pty;
    BusMemory::forget(BusMemory::key(settings));
    for (const QString& child : {QStringLiteral("3"), QStringLiteral("5")}) {
        const CliResult r =
            cli(*sim, {kBus, QStringLiteral("set"), child, QStringLiteral("comm.group=1")});
        ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    }
    ASSERT_EQ(sim->get(3, 0x00F5), 1);
    ASSERT_EQ(sim->get(5, 0x00F5), 1);
}

} // namespace

TEST(CliGroupE2e, AWriteToAGroupParentIsRefusedWithoutYesAndReadBackFromTheChildrenWithIt)
{
    SimProcess sim;
    startGroupedBus(&sim, QStringLiteral("dbu200@1,dbu200@3,dbu200@5"));
    const int before1 = sim.get(1, 0xCA03);
    const int before3 = sim.get(3, 0xCA03);
    const int before5 = sim.get(5, 0xCA03);
    ASSERT_NE(before1, 1777);

    CliResult r = cli(sim, {kBus, QStringLiteral("set"), QStringLiteral("1"),
                            QStringLiteral("spno2.speed=1777")});
    EXPECT_EQ(r.code, 3) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("also executed by 3, 5"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was sent"))) << qPrintable(r.err);
    EXPECT_EQ(sim.get(1, 0xCA03), before1);
    EXPECT_EQ(sim.get(3, 0xCA03), before3);
    EXPECT_EQ(sim.get(5, 0xCA03), before5);

    // A write to a child reaches the child only: no question asked.
    r = cli(sim,
            {kBus, QStringLiteral("set"), QStringLiteral("3"), QStringLiteral("spno2.speed=1500")});
    EXPECT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_EQ(sim.get(3, 0xCA03), 1500);
    EXPECT_EQ(sim.get(1, 0xCA03), before1);

    // Child 3 now holds 1500, 5 its old value: the report shows what each child holds after.
    r = cli(sim, {kBus, QStringLiteral("--trace"), QStringLiteral("set"), QStringLiteral("1"),
                  QStringLiteral("spno2.speed=1777"), QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("(group parent: also 3, 5)"))) << qPrintable(r.err);
    const qsizetype report =
        r.out.indexOf(QStringLiteral("Read back from the drives of the group"));
    ASSERT_GE(report, 0) << qPrintable(r.out);
    const QString children = r.out.mid(report);
    EXPECT_TRUE(children.contains(QRegularExpression(QStringLiteral("\\n3 +spno2\\.speed +1777"))))
        << qPrintable(r.out);
    EXPECT_TRUE(children.contains(QRegularExpression(QStringLiteral("\\n5 +spno2\\.speed +1777"))))
        << qPrintable(r.out);
    EXPECT_EQ(sim.get(1, 0xCA03), 1777);
    EXPECT_EQ(sim.get(3, 0xCA03), 1777);
    EXPECT_EQ(sim.get(5, 0xCA03), 1777);

    // Without a list of the drives (and no scan of this port) the children cannot be named:
    // refused, nothing sent.
    r = cli(sim, {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed=1800"),
                  QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 2) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--bus-drives"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was sent"))) << qPrintable(r.err);
    for (int id : {1, 3, 5})
        EXPECT_EQ(sim.get(id, 0xCA03), 1777) << id;
    sim.terminate();
}

TEST(CliGroupE2e, ACommandToAGroupParentNamesTheChildrenAndReportsTheirState)
{
    SimProcess sim;
    startGroupedBus(&sim, QStringLiteral("dbu200@1,dbu200@3,dbu200@5"));
    for (int id : {1, 3, 5})
        sim.command(QStringLiteral("set %1 0x100D 2").arg(id)); // communication priority

    CliResult r =
        cli(sim, {kBus, QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("start")});
    EXPECT_EQ(r.code, 2) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("also executed by 3, 5"))) << qPrintable(r.err);
    for (int id : {1, 3, 5})
        EXPECT_EQ(sim.get(id, 0x0109, 4), 0) << id;
    // An alarm reset reaches the children as well.
    r = cli(sim, {kBus, QStringLiteral("alarms"), QStringLiteral("1"), QStringLiteral("--reset")});
    EXPECT_EQ(r.code, 2) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("also executed by 3, 5"))) << qPrintable(r.err);

    r = cli(sim, {kBus, QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("start"),
                  QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("executed also by 3, 5"))) << qPrintable(r.out);
    const qsizetype at =
        r.out.indexOf(QStringLiteral("Communication group of 1, read after the command:"));
    ASSERT_GE(at, 0) << qPrintable(r.out);
    for (int id : {3, 5})
        EXPECT_TRUE(r.out.mid(at).contains(QStringLiteral("Machine number %1 runs").arg(id)))
            << qPrintable(r.out);
    sim.terminate();
}

TEST(CliGroupE2e, ScanShowsTheGroupsAndAChildOfAMissingParent)
{
    SimProcess sim;
    startGroupedBus(&sim, QStringLiteral("dbu200@1,dbu200@3,dbu200@5,dcpid@7"));
    ASSERT_EQ(
        cli(sim, {kBus, QStringLiteral("set"), QStringLiteral("5"), QStringLiteral("comm.group=9")})
            .code,
        0);
    const CliResult r =
        cli(sim, {QStringLiteral("scan"), QStringLiteral("--to"), QStringLiteral("10")});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("comm. group"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("off (parent of 3)"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("1 (child of 1)"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("9 (child of 9)"))) << qPrintable(r.out);
    EXPECT_TRUE(
        r.err.contains(QStringLiteral("machine number 5 is in communication group 9, but no "
                                      "drive 9 is known")))
        << qPrintable(r.err);
    sim.terminate();
}

namespace {

const QString kMixedBus = QStringLiteral("--bus-drives=1,2,150");

// Drives 1 and 2 (DBU200) and 150 (DBU400) on a half-duplex line with wire timing; 2 and 150
// follow 1.
void startMixedGroup(SimProcess* sim)
{
    QString error;
    ASSERT_TRUE(
        sim->start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dbu200@2,dbu400@150"),
                    QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex"),
                    QStringLiteral("--baud"), QStringLiteral("19200")},
                   &error))
        << qPrintable(error);
    for (int child : {2, 150})
        sim->command(QStringLiteral("set %1 0x00F5 1").arg(child));
    ASSERT_EQ(sim->get(2, 0x00F5), 1);
    ASSERT_EQ(sim->get(150, 0x00F5), 1);
}

} // namespace

TEST(CliGroupE2e, AValueAChildDoesNotAllowIsRefusedBeforeSendingAndADivergingChildExitsFour)
{
    SimProcess sim;
    startMixedGroup(&sim);
    const QString variants = QStringLiteral("--variant=1=dbu200,2=dbu200,150=dbu400");
    constexpr int kSpno5 = 0xCA09;
    const int before[] = {sim.get(1, kSpno5), sim.get(2, kSpno5), sim.get(150, kSpno5)};

    // 280 r/min: a DBU200 allows it, the DBU400 that follows drive 1 does not.
    CliResult r = cli(sim, {kMixedBus, variants, QStringLiteral("set"), QStringLiteral("1"),
                            QStringLiteral("spno5.speed=280"), QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 3) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("machine number 150 (DBU400-D4) executes this "
                                              "write too (communication group 1)")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("0 or 300–3000 r/min"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was written"))) << qPrintable(r.err);
    EXPECT_EQ(sim.get(1, kSpno5), before[0]);
    EXPECT_EQ(sim.get(2, kSpno5), before[1]);
    EXPECT_EQ(sim.get(150, kSpno5), before[2]);

    // Without its variant named, the child is held to the strictest range, and told so.
    r = cli(sim, {kMixedBus, QStringLiteral("--variant=1=dbu200,2=dbu200"), QStringLiteral("set"),
                  QStringLiteral("1"), QStringLiteral("spno5.speed=280"), QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 3) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("machine number 150 (DBU, variant not known)")))
        << qPrintable(r.err);
    EXPECT_EQ(sim.get(150, kSpno5), before[2]);

    // A child that does not take what its parent is sent: exit 4, and it is named.
    sim.command(QStringLiteral("defect 150 nostick=spno5.speed"));
    r = cli(sim, {kMixedBus, variants, QStringLiteral("set"), QStringLiteral("1"),
                  QStringLiteral("spno5.speed=1500"), QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 4) << qPrintable(r.out) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(
        QStringLiteral("machine number 150 holds %1 r/min, not 1500 r/min").arg(before[2])))
        << qPrintable(r.out);
    EXPECT_FALSE(r.out.contains(QStringLiteral("written, verified"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QRegularExpression(
        QStringLiteral("\\n150 +spno5\\.speed +%1 r/min +DIFFERS").arg(before[2]))))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(
        QRegularExpression(QStringLiteral("\\n2 +spno5\\.speed +1500 r/min +verified"))))
        << qPrintable(r.out);
    EXPECT_EQ(sim.get(1, kSpno5), 1500);
    EXPECT_EQ(sim.get(2, kSpno5), 1500);
    EXPECT_EQ(sim.get(150, kSpno5), before[2]);
    sim.terminate();
}

TEST(CliGroupE2e, ARunOnAParentNamesWhoWillNotFollowAndReportsWhoRuns)
{
    SimProcess sim;
    startMixedGroup(&sim);
    for (int id : {1, 2})
        sim.command(QStringLiteral("set %1 0x100D 2").arg(id)); // communication priority
    // Asked without --yes: who follows is said, nothing is sent.
    CliResult r =
        cli(sim, {kMixedBus, QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("start")});
    EXPECT_EQ(r.code, 2) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("Machine number 2 follows it"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("Machine number 150 does NOT follow it: it is in "
                                              "I/O priority")))
        << qPrintable(r.err);
    for (int id : {1, 2, 150})
        EXPECT_EQ(sim.get(id, 0x0109, 4), 0) << id;

    r = cli(sim, {kMixedBus, QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("start"),
                  QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("Machine number 150 does NOT follow it")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Machine number 2 runs"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Machine number 150 does not run: it is in I/O "
                                              "priority")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("E2h Cannot execute command: ")))
        << qPrintable(r.out);
    r = cli(sim, {kMixedBus, QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("stop"),
                  QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 0) << qPrintable(r.err);
    sim.terminate();
}
