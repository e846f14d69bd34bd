// The command line knows its bus (issue 27): a scan is remembered per connection in the memory
// the window shares, and a write or command to a group parent then names the children without
// --bus-drives, reading their groups again; with nothing remembered it refuses, sending nothing.
// opentop-cli over a pty against opentop-sim.
#include "model/bus/BusMemory.h"
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"
#include "transport/ConnectionSettings.h"

using namespace opentop;
using namespace opentop::test;

namespace {

CliResult cli(const SimProcess& sim, const QStringList& args)
{
    return runCliOn(sim.pty, args);
}

QString keyOf(const SimProcess& sim)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Serial;
    settings.port = sim.pty;
    return BusMemory::key(settings);
}

// Drives 1, 3 and 5 of one model; 3 and 5 are children of 1 (set through the simulator's
// console: nothing on the command line knows the bus yet).
void startGroupOfThree(SimProcess* sim)
{
    QString error;
    ASSERT_TRUE(sim->start(
        {QStringLiteral("--devices"), QStringLiteral("dbu200@1,dbu200@3,dbu200@5")}, &error))
        << qPrintable(error);
    // A pty's name comes back for the next simulator: what an earlier test remembered for it
    // is not this bus.
    BusMemory::forget(keyOf(*sim));
    for (int child : {3, 5})
        sim->command(QStringLiteral("set %1 0x00F5 1").arg(child));
    ASSERT_EQ(sim->get(3, 0x00F5), 1);
    ASSERT_EQ(sim->get(5, 0x00F5), 1);
}

CliResult scan(const SimProcess& sim)
{
    return cli(sim, {QStringLiteral("scan"), QStringLiteral("--to"), QStringLiteral("8")});
}

} // namespace

TEST(CliBusMemoryE2e, WithNothingKnownAWriteOrCommandToAPossibleParentIsRefusedAndChangesNothing)
{
    SimProcess sim;
    startGroupOfThree(&sim);
    const int speed = sim.get(1, 0xCA03);
    CliResult r = cli(sim, {QStringLiteral("set"), QStringLiteral("1"),
                            QStringLiteral("spno2.speed=1777"), QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 2) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was sent"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("opentop-cli scan"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--no-group-check"))) << qPrintable(r.err);
    for (int id : {1, 3, 5})
        EXPECT_EQ(sim.get(id, 0xCA03), speed) << id;
    for (int id : {1, 3, 5})
        sim.command(QStringLiteral("set %1 0x100D 2").arg(id)); // communication priority
    r = cli(sim, {QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("start"),
                  QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 2) << qPrintable(r.err);
    for (int id : {1, 3, 5})
        EXPECT_EQ(sim.get(id, 0x0109, 4), 0) << "machine number " << id << " runs";
    // Reading stays free.
    r = cli(sim, {QStringLiteral("get"), QStringLiteral("1"), QStringLiteral("spno2.speed")});
    EXPECT_EQ(r.code, 0) << qPrintable(r.err);
    // Asked for by name, it goes, and says what it did not look for.
    r = cli(sim, {QStringLiteral("--no-group-check"), QStringLiteral("set"), QStringLiteral("1"),
                  QStringLiteral("spno2.speed=1777")});
    EXPECT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--no-group-check"))) << qPrintable(r.err);
    sim.terminate();
}

TEST(CliBusMemoryE2e, AfterAScanSetAndRunToTheParentNameTheChildrenWithoutAList)
{
    SimProcess sim;
    startGroupOfThree(&sim);
    CliResult r = scan(sim);
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("remembered for"))) << qPrintable(r.err);
    // The memory the window reads: the same drives, with when.
    const QVector<BusMemory::Drive> remembered = BusMemory::load(keyOf(sim));
    ASSERT_EQ(remembered.size(), 3);
    EXPECT_EQ(remembered[1].slave, 3);
    EXPECT_TRUE(BusMemory::savedAt(keyOf(sim)).isValid());

    const int speed = sim.get(1, 0xCA03);
    r = cli(sim, {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed=1777")});
    EXPECT_EQ(r.code, 3) << qPrintable(r.err); // a parent needs --yes
    EXPECT_TRUE(r.err.contains(QStringLiteral("also executed by 3, 5"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("the last scan of %1").arg(sim.pty)))
        << qPrintable(r.err);
    EXPECT_EQ(sim.get(3, 0xCA03), speed);
    r = cli(sim, {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed=1777"),
                  QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    for (int id : {1, 3, 5})
        EXPECT_EQ(sim.get(id, 0xCA03), 1777) << id;

    for (int id : {1, 3, 5})
        sim.command(QStringLiteral("set %1 0x100D 2").arg(id));
    r = cli(sim, {QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("start")});
    EXPECT_EQ(r.code, 2) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("also executed by 3, 5"))) << qPrintable(r.err);
    for (int id : {1, 3, 5})
        EXPECT_EQ(sim.get(id, 0x0109, 4), 0) << id;
    sim.terminate();
}

TEST(CliBusMemoryE2e, ARememberedChildThatLeftTheGroupIsNoLongerNamed)
{
    SimProcess sim;
    startGroupOfThree(&sim);
    ASSERT_EQ(scan(sim).code, 0);
    // Since the scan, 5 left the group (its own number again): the groups are read again.
    sim.command(QStringLiteral("set 5 0x00F5 5"));
    const CliResult r =
        cli(sim, {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed=1600")});
    EXPECT_EQ(r.code, 3) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("also executed by 3 "))) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("also executed by 3, 5"))) << qPrintable(r.err);
    sim.terminate();
}

TEST(CliBusMemoryE2e, TheDrivesTheWindowRememberedAreTheCommandLines)
{
    SimProcess sim;
    startGroupOfThree(&sim);
    // What the window keeps after its scan (BusRecallBar saves its bus list through
    // BusMemory::save, which keeps the drives present).
    QVector<DeviceInfo> found;
    for (int slave : {1, 3, 5}) {
        DeviceInfo info;
        info.slave = slave;
        info.state = DeviceInfo::State::Present;
        info.family = QStringLiteral("dbu");
        info.variant = QStringLiteral("dbu200");
        info.model = QStringLiteral("DBU200");
        found << info;
    }
    BusMemory::save(keyOf(sim), BusMemory::present(found));
    const CliResult r =
        cli(sim, {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed=1600")});
    EXPECT_EQ(r.code, 3) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("also executed by 3, 5"))) << qPrintable(r.err);
    sim.terminate();
}
