// The RTU backend's quiet time after a timeout with nothing received: deferred until the next
// request to the same slave (or a broadcast), so that asking many absent machine numbers costs
// one wait each, while a late reply is still never taken for another request's answer. At 1200
// baud the quiet time after a one-register read is ceil(10.5 × 8.33) + 10 = 98 ms.
#include "RtuBackend.h"
#include "RtuFrame.h"
#include "TrafficLog.h"
#include "TransportTestSupport.h"

#include <QElapsedTimer>
#include <QThread>
#include <gtest/gtest.h>

using namespace opentop;
using namespace opentop::test;

namespace {

std::unique_ptr<RtuBackend> openBackend(const PtyDevice& device, TrafficLog* log)
{
    ConnectionSettings s;
    s.port = device.path();
    s.baud = 1200;
    s.parity = 'N';
    auto backend = std::make_unique<RtuBackend>(s);
    backend->setTrafficLog(log);
    QString error;
    EXPECT_TRUE(backend->open(&error)) << error.toStdString();
    return backend;
}

Answer answer(quint8 slave, quint16 value, int delayMs = 0)
{
    Answer a;
    a.bytes = RtuFrame::encodeReadReply(slave, 0x03, {value});
    a.delayMs = delayMs;
    return a;
}

} // namespace

TEST(RtuDeferredRecoveryTest, SilentTimeoutDoesNotDelayARequestToAnotherSlave)
{
    PtyDevice device;
    device.start([](const QByteArray& request) {
        return quint8(request.at(0)) == 2 ? answer(2, 22) : Answer();
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    QThread::msleep(1100); // past the check of every reply that follows opening the port
    EXPECT_EQ(backend->transact(ModbusRequest::readHolding(1, 0, 1), 50).error,
              ModbusError::Timeout);
    QElapsedTimer timer;
    timer.start();
    const ModbusResult r = backend->transact(ModbusRequest::readHolding(2, 0, 1), 300);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({22}));
    EXPECT_LT(timer.elapsed(), 60); // not after the 98 ms quiet time
}

TEST(RtuDeferredRecoveryTest, LateReplyFromAnotherSlaveIsRejected)
{
    // Slave 1 answers 40 ms after the client gave up, while slave 2 is being asked: the late
    // frame carries id 1 and must not pass for slave 2's answer.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        const quint8 slave = quint8(request.at(0));
        return slave == 1 ? answer(1, 1111, 90) : answer(2, 2222, 20);
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    EXPECT_EQ(backend->transact(ModbusRequest::readHolding(1, 0, 1), 50).error,
              ModbusError::Timeout);
    ModbusResult r = backend->transact(ModbusRequest::readHolding(2, 0, 1), 300);
    EXPECT_EQ(r.error, ModbusError::WrongSlave) << r.errorText().toStdString();
    EXPECT_FALSE(r.registers.contains(1111));
    // The rejection drained slave 2's own reply as well: the next answer is clean.
    r = backend->transact(ModbusRequest::readHolding(2, 0, 1), 300);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({2222}));
}

TEST(RtuDeferredRecoveryTest, BroadcastWaitsOutTheQuietTime)
{
    PtyDevice device;
    device.start([](const QByteArray&) { return Answer(); });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    backend->setTurnaroundMs(1);
    EXPECT_EQ(backend->transact(ModbusRequest::readHolding(1, 0, 1), 50).error,
              ModbusError::Timeout);
    QElapsedTimer timer;
    timer.start();
    EXPECT_EQ(backend->transact(ModbusRequest::writeSingle(0, 0x2000, 1), 100).error,
              ModbusError::Ok);
    EXPECT_GE(timer.elapsed(), 90); // the rest of the 98 ms, then the frame itself
}

TEST(RtuDeferredRecoveryTest, BytesArrivingBeforeSendingAreDrainedFirst)
{
    // Slave 1's late reply is already on the line when slave 3 is to be asked: it is read and
    // discarded, the line is left quiet, and only then does the request go out.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        const quint8 slave = quint8(request.at(0));
        return slave == 1 ? answer(1, 1111, 60) : answer(3, 3333);
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    EXPECT_EQ(backend->transact(ModbusRequest::readHolding(1, 0, 1), 50).error,
              ModbusError::Timeout);
    QElapsedTimer wait;
    wait.start();
    while (wait.elapsed() < 30) // let the late reply arrive
        QThread::msleep(5);
    const ModbusResult r = backend->transact(ModbusRequest::readHolding(3, 0, 1), 300);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({3333}));
    bool discarded = false;
    for (const TrafficEntry& e : log.entries())
        discarded |= e.error.contains(QStringLiteral("discarded")) &&
                     e.bytes == RtuFrame::encodeReadReply(1, 0x03, {1111});
    EXPECT_TRUE(discarded);
}
