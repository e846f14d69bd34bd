// Routing on the simulated line: machine numbers, broadcast, DBU group communication, silence
// for unknown ids and bad CRCs, bus specs and line settings.
#include "tests/sim/SimTestSupport.h"

using namespace opentop;
using namespace opentop::test;

TEST(SimBus, FromSpecCreatesTheFamiliesDevices)
{
    QString error;
    auto bus = SimBus::fromSpec(QStringLiteral("dbu200@1,dbu400@150,dcpid@7"), &error);
    ASSERT_TRUE(bus) << error.toStdString();
    ASSERT_EQ(bus->devices().size(), 3);
    EXPECT_EQ(bus->device(150)->variant(), QStringLiteral("dbu400"));
    EXPECT_EQ(bus->device(7)->profile().family, QStringLiteral("dcpid"));
    EXPECT_EQ(bus->spec(), QStringLiteral("dbu200@1,dcpid@7,dbu400@150"));
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dbu200@1,dcpid@1"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("1"))) << error.toStdString();
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("abc@1"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("dbu200"))) << error.toStdString();
}

TEST(SimBus, UnknownIdAndBadCrcAreSilent)
{
    SimFixture sim("dbu200@1");
    EXPECT_FALSE(sim.read(2, 3, 0xCA03).replied);
    QByteArray frame = withCrc(hexBytes("01 06 CA 03 07 D0"));
    frame[frame.size() - 1] = char(frame.at(frame.size() - 1) ^ 1);
    EXPECT_FALSE(sim.send(frame).replied);
    EXPECT_EQ(sim.readOne(1, "spno2.speed"), 1000); // not executed either
    EXPECT_FALSE(sim.send(hexBytes("01 03")).replied);
}

TEST(SimBus, BroadcastWritesEveryDeviceWithoutReply)
{
    SimFixture sim("dbu200@1,dbu400@2,dcpid@7");
    const Answer a = sim.write(0, 0xCA03, 2000);
    EXPECT_FALSE(a.replied);
    EXPECT_EQ(sim.readOne(1, "spno2.speed"), 2000);
    EXPECT_EQ(sim.readOne(2, "spno2.speed"), 2000);
    EXPECT_EQ(sim.device(7)->lastError(), SimError::IllegalAddress); // no such register: silent
    EXPECT_FALSE(sim.read(0, 3, 0xCA03).replied);                    // reads are not broadcast
    EXPECT_EQ(sim.raw(1, "status.comm_error"), 0);
}

TEST(SimBus, GroupMembersExecuteWritesToTheirGroupSilently)
{
    SimFixture sim("dbu200@1,dbu200@2,dbu200@3,dbu200@4");
    ASSERT_TRUE(sim.write(3, "comm.group", 1).ok());
    ASSERT_TRUE(sim.write(4, "comm.group", 2).ok());
    const Answer a = sim.write(1, "spno2.speed", 1500);
    EXPECT_EQ(a.adu, withCrc(hexBytes("01 06 CA 03 05 DC"))); // only the parent replies
    EXPECT_EQ(sim.raw(3, "spno2.speed"), 1500);
    EXPECT_EQ(sim.raw(2, "spno2.speed"), 1000);
    EXPECT_EQ(sim.raw(4, "spno2.speed"), 1000);
    // Children never reply, also to a value they refuse; reads are not propagated.
    EXPECT_EQ(sim.write(1, "spno2.speed", 100).exception, 0x04);
    EXPECT_EQ(sim.raw(3, "status.comm_error"), 0xE8);
    EXPECT_EQ(sim.read(1, 3, 0x0000).exception, 0x02);
    EXPECT_EQ(sim.raw(3, "status.comm_error"), 0xE8);
    EXPECT_EQ(sim.raw(1, "status.comm_error"), 0xE0);
}

TEST(SimBus, GroupAddressWithoutParentDevice)
{
    SimFixture sim("dbu200@1,dbu200@2");
    ASSERT_TRUE(sim.write(1, "comm.group", 9).ok());
    ASSERT_TRUE(sim.write(2, "comm.group", 9).ok());
    EXPECT_FALSE(sim.write(9, sim.address(1, "spno3.speed"), 2222).replied);
    EXPECT_EQ(sim.raw(1, "spno3.speed"), 2222);
    EXPECT_EQ(sim.raw(2, "spno3.speed"), 2222);
}

TEST(SimBus, GroupStartsSeveralMotors)
{
    SimFixture sim("dbu200@1,dbu200@2");
    for (int id : {1, 2})
        ASSERT_TRUE(sim.write(id, "core.control_priority", 2).ok());
    ASSERT_TRUE(sim.write(2, "comm.group", 1).ok());
    ASSERT_TRUE(sim.write(1, "run.select", 1).ok());
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(2000);
    EXPECT_EQ(sim.raw(1, "status.current_speed"), 1000);
    EXPECT_EQ(sim.raw(2, "status.current_speed"), 1000);
}

TEST(SimBus, DevicesAtAnotherBaudDoNotHear)
{
    SimFixture sim("dbu200@1,dcpid@7");
    sim.bus->setLine(19200, 'N');
    EXPECT_EQ(sim.raw(7, "config.baud"), 19200); // configured to match the line
    EXPECT_EQ(sim.raw(7, "config.parity"), 0);
    EXPECT_TRUE(sim.read(7, 3, 0x0010).ok());
    ASSERT_TRUE(sim.write(1, "comm.rate", 0).ok()); // 9600 after power-on
    EXPECT_TRUE(sim.read(1, 3, 0xCA03).ok());
    sim.device(1)->powerCycle(sim.clock->nowMs());
    EXPECT_FALSE(sim.read(1, 3, 0xCA03).replied);
    EXPECT_TRUE(sim.read(7, 3, 0x0010).ok());
}

TEST(SimBus, ConsoleControlReachesTheDevice)
{
    SimFixture sim("dbu200@1");
    const SimControlResult get =
        sim.bus->control(1, {QStringLiteral("get"), QStringLiteral("0xCA03")});
    EXPECT_TRUE(get.ok);
    EXPECT_TRUE(get.text.startsWith(QStringLiteral("0xca03 = 1000"))) << get.text.toStdString();
    EXPECT_TRUE(sim.bus
                    ->control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"),
                                  QStringLiteral("77"), QStringLiteral("3")})
                    .ok);
    EXPECT_EQ(sim.device(1)->reg(3, 0xCA03), 77); // no validation through the backdoor
    EXPECT_FALSE(sim.bus->control(5, {QStringLiteral("get"), QStringLiteral("1")}).ok);
    EXPECT_FALSE(sim.bus->control(1, {QStringLiteral("get"), QStringLiteral("zz")}).ok);
    EXPECT_FALSE(sim.bus->control(1, {QStringLiteral("frobnicate")}).ok);
}
