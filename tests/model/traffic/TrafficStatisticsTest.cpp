#include "model/traffic/TrafficStatistics.h"
#include "tests/model/DriveSimFixture.h"

#include "sim/FaultInjector.h"
#include "transport/ModbusRequest.h"
#include "transport/RtuFrame.h"

using namespace opentop;
using namespace opentop::test;

namespace {

TrafficEntry frame(TrafficEntry::Direction direction, int slave, int function,
                   const QString& error = QString(), double ms = -1)
{
    TrafficEntry e;
    e.direction = direction;
    e.slave = quint8(slave);
    e.function = quint8(function);
    e.error = error;
    e.responseMs = ms;
    return e;
}

} // namespace

TEST(TrafficStatisticsTest, CountsPerDrive)
{
    using D = TrafficEntry::Direction;
    TrafficStatistics stats;
    stats.add(frame(D::Tx, 1, 3));
    stats.add(frame(D::Rx, 1, 3, QString(), 10));
    stats.add(frame(D::Tx, 1, 3));
    stats.add(frame(D::Rx, 1, 0x83, QString(), 30));
    stats.add(frame(D::Tx, 2, 3));
    stats.add(frame(D::Event, 2, 3, modbusErrorName(ModbusError::Timeout)));
    stats.add(frame(D::Tx, 2, 3));
    stats.add(frame(D::Rx, 2, 3, modbusErrorName(ModbusError::CrcError), 5));
    stats.add(frame(D::Tx, 2, 3));
    stats.add(frame(D::Rx, 9, 3, modbusErrorName(ModbusError::WrongSlave), 7)); // counts for 2

    EXPECT_EQ(stats.slaves(), (QVector<int>{1, 2}));
    const DriveTrafficStats one = stats.drive(1);
    EXPECT_EQ(one.requests, 2);
    EXPECT_EQ(one.replies, 2);
    EXPECT_EQ(one.exceptions, 1);
    EXPECT_DOUBLE_EQ(one.meanMs(), 20.0);
    EXPECT_DOUBLE_EQ(one.maxMs, 30.0);
    const DriveTrafficStats two = stats.drive(2);
    EXPECT_EQ(two.requests, 3);
    EXPECT_EQ(two.replies, 2);
    EXPECT_EQ(two.timeouts, 1);
    EXPECT_EQ(two.crcErrors, 1);
    EXPECT_EQ(two.garbled, 1);
    EXPECT_EQ(two.errors(), 3);
    EXPECT_EQ(stats.total().requests, 5);
    stats.clear();
    EXPECT_TRUE(stats.slaves().isEmpty());
}

class TrafficStatisticsSimTest : public DriveSimFixture
{
};

TEST_F(TrafficStatisticsSimTest, CountsFaultsOnTheSimulatedBus)
{
    startBus(QStringLiteral("dbu200@1"));
    auto read = [this](int slave) {
        return await<ModbusResult>([this, slave](auto done) {
            client->submit(ModbusRequest::readHolding(quint8(slave), 0xCA03, 1), nullptr, done);
        });
    };
    EXPECT_TRUE(read(1).ok());
    EXPECT_EQ(read(5).error, ModbusError::Timeout); // nobody at 5
    bus->setFaults(FaultInjector(*FaultInjector::parse(QStringLiteral("crc=1"), nullptr)));
    EXPECT_EQ(read(1).error, ModbusError::CrcError);
    bus->setFaults(FaultInjector());

    TrafficStatistics stats;
    for (const TrafficEntry& e : log.entries())
        stats.add(e);
    const DriveTrafficStats one = stats.drive(1);
    EXPECT_EQ(one.requests, 2);
    EXPECT_EQ(one.replies, 2);
    EXPECT_EQ(one.crcErrors, 1);
    EXPECT_EQ(one.timeouts, 0);
    EXPECT_GE(one.maxMs, one.meanMs());
    const DriveTrafficStats five = stats.drive(5);
    EXPECT_EQ(five.requests, 1);
    EXPECT_EQ(five.timeouts, 1);
    EXPECT_EQ(five.replies, 0);
}

TEST(TrafficStatisticsTest, AddressesThatNeverAnsweredAreListedAsRanges)
{
    using D = TrafficEntry::Direction;
    TrafficStatistics stats;
    for (int slave : {1, 2, 3, 5, 7, 8, 9}) {
        stats.add(frame(D::Tx, slave, 3));
        if (slave == 1 || slave == 7)
            stats.add(frame(D::Rx, slave, 3, QString(), 4));
        else
            stats.add(frame(D::Event, slave, 3, modbusErrorName(ModbusError::Timeout)));
    }
    stats.add(frame(D::Tx, 0, 6)); // a broadcast gets no answer, and expects none
    EXPECT_EQ(stats.unanswered(), (QVector<int>{2, 3, 5, 8, 9}));
    EXPECT_EQ(TrafficStatistics::rangesText(stats.unanswered()), QStringLiteral("2–3, 5, 8–9"));
    EXPECT_EQ(TrafficStatistics::rangesText({}), QString());
}

TEST(TrafficStatisticsTest, LateFramesCountForTheirSenderAndNotAsReplies)
{
    // A late reply discarded while drive 2 was asked: it is drive 1's (its id and CRC say so),
    // and it is neither a reply to drive 2 nor garbled. Debris without a frame counts for the
    // drive asked.
    using D = TrafficEntry::Direction;
    TrafficStatistics stats;
    stats.add(frame(D::Tx, 2, 3));
    TrafficEntry late = frame(D::Rx, 2, 3, QStringLiteral("late reply discarded"));
    late.kind = TrafficEntry::Kind::Late;
    late.bytes = RtuFrame::encodeReadReply(1, 0x03, {1111});
    stats.add(late);
    late.bytes = QByteArray::fromHex("01ff");
    stats.add(late);
    stats.add(frame(D::Rx, 2, 3, QString(), 20));
    EXPECT_EQ(stats.drive(1).late, 1);
    EXPECT_EQ(stats.drive(1).replies, 0);
    EXPECT_EQ(stats.drive(2).late, 1);
    EXPECT_EQ(stats.drive(2).replies, 1);
    EXPECT_EQ(stats.drive(2).garbled, 0);
    EXPECT_EQ(stats.total().late, 2);
}
