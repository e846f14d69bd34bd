// The in-process simulated backend: frames through RtuFrame, the traffic log, faults as
// timeouts, wire timing.
#include "tests/sim/SimTestSupport.h"

#include "sim/SimBackend.h"
#include "transport/DeviceIdentification.h"
#include "transport/ModbusRequest.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficLog.h"

#include <QElapsedTimer>

using namespace opentop;
using namespace opentop::test;

namespace {

std::shared_ptr<SimBus> makeBus(const char* spec)
{
    QString error;
    auto bus = SimBus::fromSpec(QString::fromLatin1(spec), &error);
    EXPECT_TRUE(bus) << error.toStdString();
    return bus;
}

void setFault(SimBus& bus, const QString& text)
{
    QString error;
    const auto rates = FaultInjector::parse(text, &error);
    ASSERT_TRUE(rates) << error.toStdString();
    bus.setFaults(FaultInjector(*rates, 3));
}

} // namespace

TEST(SimBackend, ReadsWritesAndLogsBothDirections)
{
    SimBackend backend(makeBus("dbu200@1,dcpid@7"));
    TrafficLog log;
    backend.setTrafficLog(&log);
    EXPECT_EQ(backend.transact(ModbusRequest::readHolding(1, 0xCA03, 1), 100).error,
              ModbusError::NotConnected);
    QString error;
    ASSERT_TRUE(backend.open(&error));
    EXPECT_EQ(backend.describe(), QStringLiteral("sim dbu200@1,dcpid@7"));

    ModbusResult r = backend.transact(ModbusRequest::readHolding(1, 0xCA03, 1), 100);
    ASSERT_TRUE(r.ok()) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, (QVector<quint16>{1000}));
    EXPECT_EQ(r.reply, hexBytes("01 03 02 03 E8 B8 FA"));

    r = backend.transact(ModbusRequest::writeSingle(1, 0xCA03, 1500), 100);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(backend.bus().device(1)->raw(QStringLiteral("spno2.speed")), 1500);

    r = backend.transact(ModbusRequest::writeSingle(1, 0x007B, 10), 100);
    EXPECT_EQ(r.error, ModbusError::Exception);
    EXPECT_EQ(r.exceptionCode, 0x02);

    const QVector<TrafficEntry> entries = log.entries();
    ASSERT_EQ(entries.size(), 6);
    EXPECT_EQ(entries.at(0).direction, TrafficEntry::Direction::Tx);
    EXPECT_EQ(entries.at(0).bytes, hexBytes("01 03 CA 03 00 01 4B D2"));
    EXPECT_EQ(entries.at(1).direction, TrafficEntry::Direction::Rx);
    EXPECT_EQ(entries.at(5).bytes, hexBytes("01 86 02 C3 A1"));
}

TEST(SimBackend, DeviceIdentificationThroughRawRequest)
{
    SimBackend backend(makeBus("dcpid@7"));
    ASSERT_TRUE(backend.open(nullptr));
    const ModbusResult r = backend.transact(ModbusRequest::readDeviceIdentification(7), 100);
    ASSERT_TRUE(r.ok()) << r.errorText().toStdString();
    DeviceIdentification id;
    ASSERT_TRUE(DeviceIdentification::parse(r.rawData, &id));
    EXPECT_EQ(id.text(1), QStringLiteral("DCPID-20A"));
}

TEST(SimBackend, BroadcastReturnsAtOnceAndIsExecuted)
{
    SimBackend backend(makeBus("dbu200@1,dbu200@2"));
    ASSERT_TRUE(backend.open(nullptr));
    const ModbusResult r = backend.transact(ModbusRequest::writeSingle(0, 0xCA03, 2500), 100);
    EXPECT_TRUE(r.ok());
    EXPECT_LT(r.elapsedMs, 50);
    EXPECT_EQ(backend.bus().device(2)->raw(QStringLiteral("spno2.speed")), 2500);
}

TEST(SimBackend, LostRepliesTimeOutAfterTheTimeout)
{
    auto bus = makeBus("dbu200@1");
    SimBackend backend(bus);
    ASSERT_TRUE(backend.open(nullptr));
    TrafficLog log;
    backend.setTrafficLog(&log);
    QElapsedTimer timer;
    timer.start();
    ModbusResult r = backend.transact(ModbusRequest::readHolding(9, 0xCA03, 1), 60);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    EXPECT_GE(timer.elapsed(), 59);
    EXPECT_LT(timer.elapsed(), 200);
    EXPECT_EQ(log.entries().last().direction, TrafficEntry::Direction::Event);

    setFault(*bus, QStringLiteral("drop=1"));
    r = backend.transact(ModbusRequest::writeSingle(1, 0xCA03, 1100), 60);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    EXPECT_EQ(bus->device(1)->raw(QStringLiteral("spno2.speed")), 1100);

    setFault(*bus, QStringLiteral("late=1")); // 1000 ms: later than the timeout
    timer.restart();
    r = backend.transact(ModbusRequest::readHolding(1, 0xCA03, 1), 60);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    EXPECT_LT(timer.elapsed(), 200);

    setFault(*bus, QStringLiteral("late=1,late_ms=30"));
    timer.restart();
    r = backend.transact(ModbusRequest::readHolding(1, 0xCA03, 1), 200);
    EXPECT_TRUE(r.ok());
    EXPECT_GE(timer.elapsed(), 29);

    setFault(*bus, QStringLiteral("crc=1"));
    r = backend.transact(ModbusRequest::readHolding(1, 0xCA03, 1), 100);
    EXPECT_EQ(r.error, ModbusError::CrcError);
}

TEST(SimBackend, WireTimingDelaysReplies)
{
    SimBackend backend(makeBus("dbu200@1"), true, 9600);
    ASSERT_TRUE(backend.open(nullptr));
    QElapsedTimer timer;
    timer.start();
    const ModbusResult r = backend.transact(ModbusRequest::readHolding(1, 0xCA03, 1), 200);
    ASSERT_TRUE(r.ok());
    // 8 + 7 bytes at 9600 bit/s (1.04 ms each) + 3.5 characters + 2 ms turnaround: 21.3 ms.
    EXPECT_GE(timer.nsecsElapsed() / 1e6, 21.0);
    EXPECT_LT(timer.elapsed(), 80);
}

TEST(WireTiming, FrameTimesPerBaudAndParity)
{
    const WireTiming none(19200, 'N', 2.0);
    EXPECT_NEAR(none.charMs(), 0.5208, 1e-3);
    EXPECT_NEAR(none.replyDelayMs(8, 7), 8 * 0.5208 + 3.5 * 0.5208 + 2 + 7 * 0.5208, 1e-3);
    const WireTiming even(9600, 'E', 0);
    EXPECT_EQ(even.bitsPerChar(), 11);
    EXPECT_NEAR(even.frameMs(8), 8 * 11 / 9.6, 1e-3);
    EXPECT_NEAR(WireTiming(115200, 'N', 0).gapMs(), 1.75, 1e-9);
}
