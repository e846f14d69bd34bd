// The RTU backend's resynchronisation (issue 11): RTU frames carry no transaction id, so a
// reply that comes after the timeout looks exactly like the answer to the next request of the
// same shape. After a timeout, a foreign or a garbled reply the backend lets the line fall
// silent for the failed request's late-reply window (one more timeout) before anything goes
// out again. At 19200 baud a frame time is about 20 ms, far shorter than the late replies here.
#include "tests/transport/TransportTestSupport.h"
#include "transport/RtuBackend.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficLog.h"

#include <QThread>
#include <atomic>
#include <gtest/gtest.h>
#include <memory>

using namespace opentop;
using namespace opentop::test;

namespace {

std::unique_ptr<RtuBackend> openBackend(const PtyDevice& device, TrafficLog* log)
{
    ConnectionSettings s;
    s.port = device.path();
    s.baud = 19200;
    s.parity = 'N';
    auto backend = std::make_unique<RtuBackend>(s);
    backend->setTrafficLog(log);
    QString error;
    EXPECT_TRUE(backend->open(&error)) << error.toStdString();
    return backend;
}

Answer answer(const QByteArray& bytes, int delayMs = 0)
{
    Answer a;
    a.bytes = bytes;
    a.delayMs = delayMs;
    return a;
}

QByteArray readReply(quint8 slave, quint16 value)
{
    return RtuFrame::encodeReadReply(slave, 0x03, {value});
}

bool discarded(const TrafficLog& log, const QByteArray& bytes)
{
    for (const TrafficEntry& e : log.entries())
        if (e.error.contains(QStringLiteral("discarded")) && e.bytes.contains(bytes))
            return true;
    return false;
}

} // namespace

TEST(RtuResyncTest, LateReplyLongAfterTheTimeoutDoesNotAnswerTheNextRead)
{
    // The drive answers the read of 0x1001 70 ms after the 100 ms timeout: several frame
    // times late. The next read, of 0x1013 with the same length, must get its own data.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        return r.address == 0x1001 ? answer(readReply(1, 1111), 170) : answer(readReply(1, 2222));
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 0x1001, 1), 100);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    r = backend->transact(ModbusRequest::readHolding(1, 0x1013, 1), 100);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({2222}));
    EXPECT_TRUE(discarded(log, readReply(1, 1111)));
}

TEST(RtuResyncTest, OwnReplyAfterAForeignOneIsDiscardedBeforeTheNextRequest)
{
    // A foreign frame (id 2) comes first; the addressed drive's own reply follows 80 ms later.
    // It answers a request that already failed and must not answer the next one.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        if (r.address != 1)
            return answer(readReply(1, r.address));
        Answer a = answer(readReply(2, 42));
        a.second = readReply(1, 999);
        a.secondDelayMs = 80;
        return a;
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 1, 1), 100);
    EXPECT_EQ(r.error, ModbusError::WrongSlave);
    r = backend->transact(ModbusRequest::readHolding(1, 5, 1), 100);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({5}));
    EXPECT_TRUE(discarded(log, readReply(1, 999)));
}

TEST(RtuResyncTest, GarbledReplyIsFollowedByTheLateAnswerWhichIsDiscarded)
{
    // A reply with a bad CRC, then (60 ms later) a well-formed one: the request failed, the
    // second frame must not become the answer to the next write.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        if (r.isRead()) {
            QByteArray bad = readReply(1, 7);
            bad[bad.size() - 1] = char(bad.at(bad.size() - 1) ^ 0x21);
            Answer a = answer(bad);
            a.second = RtuFrame::encodeWriteSingleReply(1, 0x20, 5);
            a.secondDelayMs = 60;
            return a;
        }
        return answer(RtuFrame::encodeWriteSingleReply(1, r.address, r.values.value(0)), 20);
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 7, 1), 100);
    EXPECT_EQ(r.error, ModbusError::CrcError);
    // A write of the value the stray echo carries: only the drive's own echo may confirm it.
    r = backend->transact(ModbusRequest::writeSingle(1, 0x20, 5), 100);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_TRUE(discarded(log, RtuFrame::encodeWriteSingleReply(1, 0x20, 5)));
    EXPECT_EQ(device.requests().size(), 2u);
}

TEST(RtuResyncTest, ReplyFollowedByAnotherAfterAnEarlierTimeoutIsNotTaken)
{
    // Found by the fault matrix (issue 11): the drive answers the read of 0x1001 a second
    // late, long after its late-reply window, just as the read of 0x1013 (same length) goes
    // out; the drive's own answer to that read follows. The first reply must not be taken.
    auto calls = std::make_shared<std::atomic<int>>(0);
    PtyDevice device;
    device.start([calls](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        if (r.address == 0x1001)
            return Answer(); // silent now, answers "late" with the next request
        Answer a = answer(++*calls == 1 ? readReply(1, 1111) : readReply(1, 2222));
        if (*calls == 1) {
            a.second = readReply(1, 2222);
            a.secondDelayMs = 5;
        }
        return a;
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 0x1001, 1), 100);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    QThread::msleep(400); // past the late-reply window
    r = backend->transact(ModbusRequest::readHolding(1, 0x1013, 1), 100);
    EXPECT_NE(r.registers, QVector<quint16>({1111}));
    EXPECT_EQ(r.error, ModbusError::MalformedReply) << r.errorText().toStdString();
    r = backend->transact(ModbusRequest::readHolding(1, 0x1013, 1), 100);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({2222}));
}

TEST(RtuResyncTest, RepliesOfASlaveThatNeverFailedAreTakenAtOnce)
{
    PtyDevice device;
    device.start([](const QByteArray& request) {
        Answer a = answer(readReply(1, 2222));
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        if (r.slave == 1) {
            a.second = readReply(1, 3333); // a trailing frame: not looked for without a failure
            a.secondDelayMs = 5;
        }
        return a;
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    QThread::msleep(1100); // past the check that follows opening the port
    const ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 0x1013, 1), 100);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({2222}));
}

TEST(RtuResyncTest, AReplyLeftByThePreviousProgramIsNotTakenAsTheAnswerToTheFirstRequest)
{
    // The program that used the port before gave up on a read and exited; its reply (1111)
    // arrives just as we ask the same drive the same question. Our own reply follows: the
    // first one must not be taken, the request fails and is retried.
    PtyDevice device;
    device.start([](const QByteArray&) {
        Answer a = answer(readReply(1, 1111));
        a.second = readReply(1, 2222);
        a.secondDelayMs = 5;
        return a;
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    const ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 0x1013, 1), 100);
    EXPECT_EQ(r.error, ModbusError::MalformedReply) << r.errorText().toStdString();
    EXPECT_TRUE(r.registers.isEmpty());
}

TEST(RtuResyncTest, AWholeLateReplyDiscardedBeforeTheNextRequestNamesItsSender)
{
    // A scan asks 3 with a short wait; its reply comes 40 ms late and is already waiting when
    // the master asks 4 (a busy master). The bytes are discarded, but the result says who sent
    // them, so a scanner can ask 3 again instead of passing it as silent (the soak's misses).
    PtyDevice device;
    device.start([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        return r.slave == 3 ? answer(readReply(3, 1111), 60) : answer(readReply(r.slave, 2222));
    });
    TrafficLog log;
    auto backend = openBackend(device, &log);
    ModbusResult r = backend->transact(ModbusRequest::readHolding(3, 0x1001, 1), 20);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    EXPECT_EQ(r.lateReplyFrom, -1);
    QThread::msleep(150);
    r = backend->transact(ModbusRequest::readHolding(4, 0x1001, 1), 100);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({2222}));
    EXPECT_EQ(r.lateReplyFrom, 3);
    EXPECT_TRUE(discarded(log, readReply(3, 1111)));
    // The next request after that names nobody.
    r = backend->transact(ModbusRequest::readHolding(5, 0x1001, 1), 100);
    EXPECT_EQ(r.lateReplyFrom, -1);
}
