// DBU request handling: the manual's example frames, exception codes and the communication
// error register 0x007B (manual 11-5, 12).
#include "tests/sim/SimTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class DbuProtocol : public ::testing::Test
{
protected:
    SimFixture sim{"dbu200@1"};

    quint16 commError() const { return sim.readOne(1, "status.comm_error"); }
};

} // namespace

TEST_F(DbuProtocol, ManualReadHoldingExample)
{
    // 12 "Function code 03h": SPno2 speed, 1000 r/min by default.
    const Answer a = sim.send(hexBytes("01 03 CA 03 00 01 4B D2"));
    EXPECT_EQ(a.adu, hexBytes("01 03 02 03 E8 B8 FA"));
}

TEST_F(DbuProtocol, ManualReadInputExampleAfterHallAlarm)
{
    ASSERT_TRUE(sim.bus->control(1, {QStringLiteral("alarm"), QStringLiteral("0x0B")}).ok);
    const Answer a = sim.send(hexBytes("01 04 1C 01 00 01 67 9A"));
    EXPECT_EQ(a.adu, hexBytes("01 04 02 00 0B F8 F7"));
}

TEST_F(DbuProtocol, ManualConnectionExampleEchoes)
{
    const QByteArray frame = hexBytes("01 06 00 03 00 01 B8 0A");
    EXPECT_EQ(sim.send(frame).adu, frame);
}

TEST_F(DbuProtocol, ManualSpeedSelectExamplesNeedCommunicationPriority)
{
    const QByteArray select1 = hexBytes("01 06 20 0F 00 00 B2 09");
    // The manual prints 33 CB; the CRC of 01 06 20 0F 00 02 is 33 C8 (erratum). A frame with
    // the printed CRC is ignored, as a real drive would.
    EXPECT_FALSE(sim.send(hexBytes("01 06 20 0F 00 02 33 CB")).replied);
    const QByteArray select3 = hexBytes("01 06 20 0F 00 02 33 C8");
    EXPECT_EQ(sim.send(select1).exception, 0x04); // I/O priority by default
    ASSERT_TRUE(sim.write(1, "core.control_priority", 2).ok());
    EXPECT_EQ(sim.send(select1).adu, select1);
    EXPECT_EQ(sim.send(select3).adu, select3);
    EXPECT_EQ(sim.readOne(1, "run.select"), 2);
}

TEST_F(DbuProtocol, ManualWriteMultipleExampleSetsReduction)
{
    const Answer a = sim.send(hexBytes("01 10 04 03 00 02 04 00 00 00 64 80 91"));
    EXPECT_EQ(a.adu, hexBytes("01 10 04 03 00 02 B0 F8"));
    const Answer back = sim.read(1, 3, 0x0403, 2);
    EXPECT_EQ(back.values, (QVector<quint16>{0, 100}));
}

TEST_F(DbuProtocol, WritingTheErrorRegisterIsIllegalAddress)
{
    // 11-5: 01 06 00 7B 00 0A -> 01 86 02 C3 A1 (the manual's request CRC 79 D4 is checked too).
    const QByteArray request = withCrc(hexBytes("01 06 00 7B 00 0A"));
    EXPECT_EQ(request.right(2), hexBytes("79 D4"));
    EXPECT_EQ(sim.send(request).adu, hexBytes("01 86 02 C3 A1"));
    EXPECT_EQ(commError(), 0xE0);
}

TEST_F(DbuProtocol, UnsupportedFunctionIsException01WithE0)
{
    EXPECT_EQ(sim.send(withCrc(hexBytes("01 01 00 00 00 01"))).exception, 0x01);
    EXPECT_EQ(commError(), 0xE0);
    const Answer id = sim.send(withCrc(hexBytes("01 2B 0E 01 00")));
    EXPECT_EQ(id.adu, withCrc(hexBytes("01 AB 01")));
}

TEST_F(DbuProtocol, UndefinedAddressAndWrongSpaceAreException02)
{
    EXPECT_EQ(sim.read(1, 3, 0x0000).exception, 0x02);
    EXPECT_EQ(commError(), 0xE0);
    EXPECT_EQ(sim.read(1, 4, sim.address(1, "spno2.speed")).exception, 0x02); // holding only
    EXPECT_EQ(sim.read(1, 3, sim.address(1, "status.current_speed")).exception, 0x02);
    EXPECT_EQ(sim.read(1, 3, sim.address(1, "run.start")).exception, 0x02); // write-only
    EXPECT_EQ(sim.write(1, 0x0001, 1).exception, 0x02);
}

TEST_F(DbuProtocol, BlockReadSpansUnusedRegistersInsideReadBlocks)
{
    const Answer a = sim.read(1, 3, 0x1001, 17); // 0x1001..0x1011, odd addresses used
    ASSERT_TRUE(a.ok());
    ASSERT_EQ(a.values.size(), 17);
    EXPECT_EQ(a.values.at(0x1007 - 0x1001), 3000); // upper limit
    EXPECT_EQ(a.values.at(0x100D - 0x1001), 1);    // control priority I/O
    EXPECT_EQ(a.values.at(0x1002 - 0x1001), 0);    // gap
    EXPECT_EQ(a.values.at(0x1011 - 0x1001), 30);   // overload time 3.0 s
    // Outside every read block a gap is an illegal address.
    EXPECT_EQ(sim.read(1, 3, 0x1300, 4).exception, 0x02);
    // 0x1025 (parameter initialisation) is write-only but inside the block: reads as 0.
    EXPECT_EQ(sim.read(1, 3, 0x1021, 5).values, (QVector<quint16>{2, 0, 0, 0, 0}));
}

TEST_F(DbuProtocol, CountZeroOrAbove17IsException03WithE1)
{
    EXPECT_EQ(sim.read(1, 3, 0x1001, 0).exception, 0x03);
    EXPECT_EQ(commError(), 0xE1);
    EXPECT_EQ(sim.read(1, 3, 0x1001, 18).exception, 0x03);
    EXPECT_TRUE(sim.read(1, 3, 0x1001, 17).ok());
    QVector<quint16> many(18, 1000);
    EXPECT_EQ(sim.writeMany(1, 0xCA03, many).exception, 0x03);
}

TEST_F(DbuProtocol, ByteCountNotTwiceCountIsException03)
{
    // count 1 but byte count 4 and two values.
    const Answer a = sim.send(withCrc(hexBytes("01 10 CA 03 00 01 04 03 E8 03 E8")));
    EXPECT_EQ(a.exception, 0x03);
    EXPECT_EQ(commError(), 0xE1);
    EXPECT_EQ(sim.readOne(1, "spno2.speed"), 1000);
}

TEST_F(DbuProtocol, WriteToReadOnlyRegisterIsException04WithE2)
{
    EXPECT_EQ(sim.write(1, 0xCA01, 800).exception, 0x04); // SPno1 speed comes from the VR
    EXPECT_EQ(commError(), 0xE2);
}

TEST_F(DbuProtocol, OutOfRangeValueIsException04WithE8)
{
    EXPECT_EQ(sim.write(1, "spno2.speed", 100).exception, 0x04);
    EXPECT_EQ(commError(), 0xE8);
    EXPECT_EQ(sim.readOne(1, "spno2.speed"), 1000);
    EXPECT_TRUE(sim.write(1, "spno2.speed", 250).ok()); // DBU200: 0 or 250..3000
    EXPECT_TRUE(sim.write(1, "spno2.speed", 0).ok());
    EXPECT_EQ(sim.write(1, "spno2.decel", 10).exception, 0x04); // 0.5 or 2.0..30.0 s
    EXPECT_EQ(sim.write(1, "cmd.connect", 2).exception, 0x04);
    EXPECT_EQ(sim.write(1, "comm.group", 0).exception, 0x04);
    EXPECT_TRUE(sim.write(1, "comm.group", 0xFFFF).ok());
}

TEST_F(DbuProtocol, VariantRangesDiffer)
{
    SimFixture dbu400("dbu400@3");
    EXPECT_EQ(dbu400.write(3, "spno2.speed", 250).exception, 0x04);
    EXPECT_TRUE(dbu400.write(3, "spno2.speed", 300).ok());
}

TEST_F(DbuProtocol, ErrorCodeStaysUntilTheNextError)
{
    sim.read(1, 3, 0x0000);
    EXPECT_TRUE(sim.read(1, 3, 0x1001).ok());
    EXPECT_TRUE(sim.write(1, "spno2.speed", 1200).ok());
    EXPECT_EQ(commError(), 0xE0);
    sim.device(1)->powerCycle(sim.clock->nowMs());
    EXPECT_EQ(commError(), 0);
}

TEST_F(DbuProtocol, ThirtyTwoBitSettingNeedsFunction10)
{
    EXPECT_EQ(sim.write(1, 0x0403, 5).exception, 0x02);
    EXPECT_EQ(sim.writeMany(1, 0x0403, {0, 50}).exception, 0x04); // 0.50 < 1.00
    EXPECT_EQ(commError(), 0xE8);
}

TEST_F(DbuProtocol, DeviceNameAndVersion)
{
    const Answer a = sim.read(1, 4, 0x0007, 5);
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a.values.mid(0, 4), (QVector<quint16>{0x4442, 0x5520, 0x2020, 0x2020})); // "DBU     "
    EXPECT_EQ(a.values.at(4), 0x0105);
}

TEST_F(DbuProtocol, MotionCommandsRefusedUnderIoPriorityOrOffline)
{
    for (const char* name : {"run.start", "run.direction", "run.select", "run.hold"}) {
        EXPECT_EQ(sim.write(1, name, 1).exception, 0x04) << name;
        EXPECT_EQ(commError(), 0xE2);
    }
    ASSERT_TRUE(sim.write(1, "core.control_priority", 2).ok());
    EXPECT_TRUE(sim.write(1, "run.select", 1).ok());
    ASSERT_TRUE(sim.write(1, "cmd.offline", 1).ok());
    EXPECT_EQ(sim.write(1, "run.start", 1).exception, 0x04);
    EXPECT_EQ(sim.write(1, "run.select", 2).exception, 0x04);
    ASSERT_TRUE(sim.write(1, "cmd.connect", 1).ok());
    EXPECT_TRUE(sim.write(1, "run.start", 1).ok());
}
