// A reply is taken only if it can have crossed the wire since the request was sent (issue 28,
// item 2): ReplyTiming's rule, and the RTU backend on a pty whose scripted device keeps wire
// time, where a reply already on its way when the request went out answers nothing.
#include "transport/ReplyTiming.h"
#include "tests/transport/TransportTestSupport.h"
#include "transport/RtuBackend.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficLog.h"

#include <atomic>
#include <gtest/gtest.h>
#include <memory>

using namespace opentop;
using namespace opentop::test;

TEST(ReplyTimingTest, JudgesOnlyOnceTheLineHasShownWireTime)
{
    ReplyTiming t;
    EXPECT_FALSE(t.tooEarly(1.0, 15.0)) << "nothing learned: no judgement";
    t.learn(16.0, 15.0);
    EXPECT_FALSE(t.keepsWireTime());
    t.learn(20.0, 15.0);
    ASSERT_TRUE(t.keepsWireTime());
    EXPECT_TRUE(t.tooEarly(4.2, 15.0));
    EXPECT_TRUE(t.tooEarly(0.84 * 15.0, 15.0));
    EXPECT_FALSE(t.tooEarly(0.86 * 15.0, 15.0)) << "a UART a few per cent fast";
    EXPECT_FALSE(t.tooEarly(1.0, 0.0)) << "Modbus TCP has no wire";
}

TEST(ReplyTimingTest, ALineWithoutWireTimeIsNeverJudged)
{
    // A pty to a simulator without --wire-timing answers in a fraction of the wire time.
    ReplyTiming t;
    for (int i = 0; i < 10; ++i)
        t.learn(0.2, 15.0);
    EXPECT_FALSE(t.keepsWireTime());
    EXPECT_FALSE(t.tooEarly(0.2, 15.0));
    // One fast exchange on a real line (a late reply whose own answer was lost) among many
    // slow ones does not switch the rule off.
    ReplyTiming real;
    real.learn(0.2, 15.0);
    for (int i = 0; i < 20; ++i)
        real.learn(18.0, 15.0);
    EXPECT_TRUE(real.keepsWireTime());
    real.reset();
    EXPECT_FALSE(real.keepsWireTime());
}

namespace {

// At 9600 bit/s 8N1 a read of one register (8 + 7 bytes) needs 15.6 ms on the wire.
constexpr int kWireMs = 25;

Answer onTime(const QByteArray& bytes)
{
    Answer a;
    a.bytes = bytes;
    a.delayMs = kWireMs;
    return a;
}

std::unique_ptr<RtuBackend> openAt9600(const PtyDevice& device, TrafficLog* log)
{
    ConnectionSettings s;
    s.port = device.path();
    s.baud = 9600;
    s.parity = 'N';
    auto backend = std::make_unique<RtuBackend>(s);
    backend->setTrafficLog(log);
    QString error;
    EXPECT_TRUE(backend->open(&error)) << error.toStdString();
    return backend;
}

} // namespace

TEST(ReplyTimingTest, AReplyFasterThanTheWireIsALateOneAndTheRealAnswerIsTaken)
{
    // The drive keeps wire time; when 0x0401 × 60 is read (133 bytes on the wire, 139 ms at
    // 9600 bit/s), a reply of the same length is already arriving (a late answer to an earlier
    // read: 1111s) and is complete at once. The real answer (2222s) follows on time. Before
    // issue 28 the first was taken. (A long frame, so that a busy machine's scheduling delay
    // cannot make the early one look slow enough.)
    std::atomic<bool> early{true};
    PtyDevice device;
    device.start([&early](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        if (r.address != 0x0401)
            return onTime(RtuFrame::encodeReadReply(1, 0x03, {quint16(r.address)}));
        Answer a;
        if (early.exchange(false)) {
            a.bytes = RtuFrame::encodeReadReply(1, 0x03, QVector<quint16>(60, 1111));
            a.second = RtuFrame::encodeReadReply(1, 0x03, QVector<quint16>(60, 2222));
            a.secondDelayMs = 160;
        } else {
            a.bytes = RtuFrame::encodeReadReply(1, 0x03, QVector<quint16>(60, 2222));
            a.delayMs = 160;
        }
        return a;
    });
    TrafficLog log;
    auto backend = openAt9600(device, &log);
    for (quint16 address : {0x0100, 0x0101, 0x0102}) {
        const ModbusResult r = backend->transact(ModbusRequest::readHolding(1, address, 1), 300);
        ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
        EXPECT_EQ(r.registers, QVector<quint16>({address}));
    }
    const ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 0x0401, 60), 600);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>(60, 2222));
    int late = 0;
    for (const TrafficEntry& e : log.entries()) {
        if (e.kind == TrafficEntry::Kind::Late) {
            ++late;
            EXPECT_TRUE(e.error.contains(QStringLiteral("late reply"))) << e.error.toStdString();
        }
    }
    EXPECT_EQ(late, 1);
}

TEST(ReplyTimingTest, ALateReplyAloneEndsInATimeoutNotAValue)
{
    // Only the early frame comes: the request timed out, the frame was never its answer.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        if (r.address != 0x0401)
            return onTime(RtuFrame::encodeReadReply(1, 0x03, {quint16(r.address)}));
        Answer a;
        a.bytes = RtuFrame::encodeReadReply(1, 0x03, {1111});
        return a;
    });
    TrafficLog log;
    auto backend = openAt9600(device, &log);
    for (quint16 address : {0x0100, 0x0101})
        ASSERT_EQ(backend->transact(ModbusRequest::readHolding(1, address, 1), 300).error,
                  ModbusError::Ok);
    const ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 0x0401, 1), 200);
    EXPECT_EQ(r.error, ModbusError::Timeout) << r.errorText().toStdString();
    EXPECT_TRUE(r.registers.isEmpty());
    // The line recovers: the next read gets its own value.
    const ModbusResult next = backend->transact(ModbusRequest::readHolding(1, 0x0102, 1), 300);
    ASSERT_EQ(next.error, ModbusError::Ok) << next.errorText().toStdString();
    EXPECT_EQ(next.registers, QVector<quint16>({0x0102}));
}

TEST(ReplyTimingTest, ALineWithoutWireTimeKeepsWorking)
{
    // A scripted device that answers at once (a pty simulator without wire timing): every
    // reply is faster than a wire, and every one is still taken.
    PtyDevice device;
    device.start([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        Answer a;
        a.bytes = RtuFrame::encodeReadReply(1, 0x03, {quint16(r.address)});
        return a;
    });
    TrafficLog log;
    auto backend = openAt9600(device, &log);
    for (quint16 address = 0x0100; address < 0x0108; ++address) {
        const ModbusResult r = backend->transact(ModbusRequest::readHolding(1, address, 1), 300);
        ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
        EXPECT_EQ(r.registers, QVector<quint16>({address}));
    }
}

TEST(ReplyTimingTest, AReadWhileAReadOfTheSameLengthIsUnansweredIsReadAgain)
{
    // Seed 209 of the late-reply sweep: a read of 0x4503 gets no answer in time; the next read
    // of the same length, of 0xCA03, gets 0x4503's late answer (1111) on time by the wire,
    // and its own answer is lost. Nothing about that reply can be faulted; before issue 28 it
    // was taken. Now it is confirmed by reading again, and only 0xCA03's own value is taken.
    std::atomic<int> readsOfCa03{0};
    PtyDevice device;
    device.start([&readsOfCa03](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        if (r.address == 0x4503)
            return Answer(); // answered late, below
        if (r.address == 0xCA03 && readsOfCa03++ == 0)
            return onTime(RtuFrame::encodeReadReply(1, 0x03, {1111}));
        return onTime(RtuFrame::encodeReadReply(1, 0x03, QVector<quint16>(r.count, r.address)));
    });
    TrafficLog log;
    auto backend = openAt9600(device, &log);
    for (quint16 address : {0x0100, 0x0101})
        ASSERT_EQ(backend->transact(ModbusRequest::readHolding(1, address, 1), 300).error,
                  ModbusError::Ok);
    EXPECT_EQ(backend->transact(ModbusRequest::readHolding(1, 0x4503, 1), 100).error,
              ModbusError::Timeout);
    const ModbusResult r = backend->transact(ModbusRequest::readHolding(1, 0xCA03, 1), 300);
    EXPECT_FALSE(r.registers.contains(1111)) << "the late answer to 0x4503 taken for 0xCA03";
    if (r.error == ModbusError::Ok) {
        EXPECT_EQ(r.registers, QVector<quint16>({0xCA03}));
    }
    EXPECT_GE(readsOfCa03.load(), 2);
    // A read of another length is taken at once.
    const int before = readsOfCa03.load();
    const ModbusResult other = backend->transact(ModbusRequest::readHolding(1, 0x0102, 2), 300);
    EXPECT_EQ(other.error, ModbusError::Ok) << other.errorText().toStdString();
    EXPECT_EQ(readsOfCa03.load(), before);
}
