// The RTU backend's quiet time after a timeout with nothing received: deferred until the next
// request to the same slave (or a broadcast), so that asking many absent machine numbers costs
// one wait each, while a late reply is still never taken for another request's answer. At 1200
// baud the quiet time after a one-register read is ceil(10.5 × 8.33) + 10 = 98 ms.
// Any other request waits only while the timed-out request's reply could still be on the wire
// (issue 24): until its longest reply (7 bytes: 58.3 ms) could have ended after the 50 ms wait,
// plus the 3.5-character gap (29.2 ms), 137.5 ms after it was sent. A scan's probe after a probe
// goes at once: the scan sees a collision and asks again.
#include "tests/transport/TransportTestSupport.h"
#include "transport/RtuBackend.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficLog.h"

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

// A scan's question to an address not asked before.
ModbusRequest probe(quint8 slave)
{
    ModbusRequest r = ModbusRequest::readHolding(slave, 0, 1);
    r.probe = true;
    return r;
}

} // namespace

TEST(RtuDeferredRecoveryTest, SilentTimeoutDoesNotDelayAScanProbeOfAnotherSlave)
{
    PtyDevice device;
    device.start([](const QByteArray& request) {
        return quint8(request.at(0)) == 2 ? answer(2, 22) : Answer();
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    QThread::msleep(1100); // past the check of every reply that follows opening the port
    EXPECT_EQ(backend->transact(probe(1), 50).error, ModbusError::Timeout);
    QElapsedTimer timer;
    timer.start();
    const ModbusResult r = backend->transact(probe(2), 300);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({22}));
    EXPECT_LT(timer.elapsed(), 60); // neither the 98 ms quiet time nor the held line
}

TEST(RtuDeferredRecoveryTest, AfterASilentTimeoutNoOtherRequestGoesOutWhileAReplyMayBeOnTheWire)
{
    // Slave 1 never answers; a poll of slave 2, a write and a scan's probe that follow a
    // request that was not a probe each wait until slave 1's longest reply could have ended.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        if (quint8(request.at(0)) != 2)
            return Answer();
        Answer a;
        a.bytes = request.at(1) == 0x06 ? request : RtuFrame::encodeReadReply(2, 0x03, {22});
        return a;
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    QThread::msleep(1100); // past the check of every reply that follows opening the port
    ModbusRequest poll = ModbusRequest::readHolding(2, 0, 1);
    poll.priority = ModbusRequest::Priority::Poll;
    for (const ModbusRequest& next : {poll, ModbusRequest::writeSingle(2, 0, 5), probe(2)}) {
        QElapsedTimer sent;
        sent.start();
        EXPECT_EQ(backend->transact(ModbusRequest::readHolding(1, 0, 1), 50).error,
                  ModbusError::Timeout);
        const ModbusResult r = backend->transact(next, 300);
        ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
        // Sent 137.5 ms after slave 1's request at the earliest; the reply took 8 more bytes
        // each way at 1200 baud (no wire timing on a pty: a few ms).
        EXPECT_GE(sent.elapsed(), 137) << next.describe().toStdString();
        EXPECT_LT(sent.elapsed(), 250) << next.describe().toStdString();
    }
}

TEST(RtuDeferredRecoveryTest, AReplyComingWhileTheLineIsHeldIsDiscardedAndNamed)
{
    // Slave 1's reply begins 40 ms after the 50 ms wait ended: the request to slave 2 waits
    // for it instead of meeting it on the line, and its result names slave 1 (a scan asks it
    // again). The wait ends once the line is quiet after it, before the held time is over.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        const quint8 slave = quint8(request.at(0));
        return slave == 1 ? answer(1, 1111, 90) : answer(2, 2222);
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    QElapsedTimer sent;
    sent.start();
    EXPECT_EQ(backend->transact(ModbusRequest::readHolding(1, 0, 1), 50).error,
              ModbusError::Timeout);
    const ModbusResult r = backend->transact(ModbusRequest::readHolding(2, 0, 1), 300);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({2222}));
    EXPECT_EQ(r.lateReplyFrom, 1);
    EXPECT_GE(sent.elapsed(), 90);
    bool discarded = false;
    for (const TrafficEntry& e : log.entries())
        discarded |= e.error.contains(QStringLiteral("discarded")) &&
                     e.bytes == RtuFrame::encodeReadReply(1, 0x03, {1111});
    EXPECT_TRUE(discarded);
}

TEST(RtuDeferredRecoveryTest, LateReplyFromAnotherSlaveIsRejected)
{
    // Slave 1 answers 40 ms after the scan's probe gave up, while the next probe (to slave 2)
    // waits for its answer: the late frame carries id 1 and must not pass for slave 2's answer.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        const quint8 slave = quint8(request.at(0));
        return slave == 1 ? answer(1, 1111, 90) : answer(2, 2222, 20);
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    EXPECT_EQ(backend->transact(probe(1), 50).error, ModbusError::Timeout);
    ModbusResult r = backend->transact(probe(2), 300);
    // Arriving while the line is kept quiet before the probe (issue 28), the late frame is
    // discarded and the probe gets its own answer; arriving after it went out, it is rejected.
    if (r.error == ModbusError::Ok)
        EXPECT_EQ(r.registers, QVector<quint16>({2222}));
    else
        EXPECT_EQ(r.error, ModbusError::WrongSlave) << r.errorText().toStdString();
    EXPECT_FALSE(r.registers.contains(1111));
    // Either way slave 2's own reply is not left for the next request: the next answer is clean.
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

TEST(RtuDeferredRecoveryTest, AGarbledFrameDiscardedBeforeARequestIsReportedWithIt)
{
    // Slave 1's reply comes 60 ms late and garbled (it met another request on the line): it
    // is thrown away before the request to slave 2 goes out, and that request's result says
    // so (a scan asks the addresses before again); it names no sender, for it has none.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        if (quint8(request.at(0)) == 2)
            return answer(2, 2222);
        Answer a = answer(1, 1111, 60);
        a.bytes[a.bytes.size() - 1] = char(a.bytes.at(a.bytes.size() - 1) ^ 0xA5);
        return a;
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    EXPECT_EQ(backend->transact(probe(1), 50).error, ModbusError::Timeout);
    QThread::msleep(40); // the wreck arrives
    ModbusResult r = backend->transact(probe(2), 300);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_TRUE(r.discardedGarbled);
    EXPECT_EQ(r.lateReplyFrom, -1);
    r = backend->transact(probe(2), 300);
    EXPECT_FALSE(r.discardedGarbled); // once
}
