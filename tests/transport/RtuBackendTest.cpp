// RtuBackend end to end over an openpty() pair; a thread in the test plays the device with
// exact reply bytes. Ptys ignore baud and parity, so timing-related tests set a low baud rate
// only to lengthen the backend's own frame-time arithmetic.
#include "transport/RtuBackend.h"
#include "tests/transport/TransportTestSupport.h"
#include "transport/DeviceIdentification.h"
#include "transport/ModbusClient.h"
#include "transport/ModbusCrc.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficLog.h"

#include <QElapsedTimer>
#include <QThread>
#include <algorithm>
#include <gtest/gtest.h>

using namespace opentop;
using namespace opentop::test;

namespace {

QByteArray hex(const char* text)
{
    return RtuFrame::fromHex(QString::fromLatin1(text));
}

ConnectionSettings ptySettings(const QString& path, int baud = 19200)
{
    ConnectionSettings s;
    s.port = path;
    s.baud = baud;
    s.parity = 'N'; // E/O fail on ptys (tcsetattr EINVAL)
    s.timeoutMs = 200;
    return s;
}

QByteArray readReply(quint8 slave, quint16 value)
{
    return RtuFrame::encodeReadReply(slave, 0x03, {value});
}

QByteArray deviceIdReply(quint8 slave)
{
    DeviceIdentification id;
    id.objects[0] = "OpenTOP test";
    id.objects[1] = "DCPID-20A";
    id.objects[2] = "V1.02";
    return RtuFrame::encodeRaw(slave, 0x2B, id.encode());
}

struct RtuFixture
{
    PtyDevice device;
    TrafficLog log;
    std::unique_ptr<RtuBackend> backend;

    explicit RtuFixture(Script script, int baud = 19200)
    {
        device.start(std::move(script));
        backend = std::make_unique<RtuBackend>(ptySettings(device.path(), baud));
        backend->setTrafficLog(&log);
        QString error;
        EXPECT_TRUE(backend->open(&error)) << error.toStdString();
    }
    ~RtuFixture() { backend.reset(); }

    QVector<TrafficEntry> entries(TrafficEntry::Direction direction) const
    {
        QVector<TrafficEntry> found;
        for (const TrafficEntry& e : log.entries())
            if (e.direction == direction)
                found << e;
        return found;
    }
};

Answer reply(const QByteArray& bytes, int delayMs = 0)
{
    Answer a;
    a.bytes = bytes;
    a.delayMs = delayMs;
    return a;
}

} // namespace

TEST(RtuBackendTest, ReadAndWriteWithManualBytes)
{
    RtuFixture f([](const QByteArray& request) {
        if (request == hex("01 03 CA 03 00 01 4B D2"))
            return reply(hex("01 03 02 03 E8 B8 FA"));
        if (request == hex("01 06 00 03 00 01 B8 0A"))
            return reply(request);
        if (request == hex("01 10 04 03 00 02 04 00 00 00 64 80 91"))
            return reply(hex("01 10 04 03 00 02 B0 F8"));
        return Answer();
    });
    ModbusResult r = f.backend->transact(ModbusRequest::readHolding(1, 0xCA03, 1), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({1000}));
    EXPECT_EQ(r.reply, hex("01 03 02 03 E8 B8 FA"));
    r = f.backend->transact(ModbusRequest::writeSingle(1, 0x0003, 1), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    r = f.backend->transact(ModbusRequest::writeMultiple(1, 0x0403, {0, 100}), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(f.device.requests().size(), 3u);

    const auto tx = f.entries(TrafficEntry::Direction::Tx);
    const auto rx = f.entries(TrafficEntry::Direction::Rx);
    ASSERT_EQ(tx.size(), 3);
    ASSERT_EQ(rx.size(), 3);
    EXPECT_EQ(tx[0].bytes, hex("01 03 CA 03 00 01 4B D2"));
    EXPECT_EQ(tx[0].summary, QStringLiteral("read 03 0xCA03 ×1"));
    EXPECT_EQ(rx[0].bytes, hex("01 03 02 03 E8 B8 FA"));
    EXPECT_EQ(rx[0].summary, QStringLiteral("→ 1000"));
    EXPECT_GE(rx[0].responseMs, 0);
    EXPECT_TRUE(rx[0].error.isEmpty());
}

TEST(RtuBackendTest, ExceptionReply)
{
    RtuFixture f([](const QByteArray&) { return reply(hex("01 86 02 C3 A1")); });
    const ModbusResult r = f.backend->transact(ModbusRequest::writeSingle(1, 0x007B, 10), 200);
    EXPECT_EQ(r.error, ModbusError::Exception);
    EXPECT_EQ(r.exceptionCode, 2);
    const auto rx = f.entries(TrafficEntry::Direction::Rx);
    ASSERT_EQ(rx.size(), 1);
    EXPECT_EQ(rx[0].function, 0x86);
    EXPECT_EQ(rx[0].summary, QStringLiteral("exception 02 Illegal data address"));
}

TEST(RtuBackendTest, BadCrcThenNextRequestIsClean)
{
    RtuFixture f([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        QByteArray bytes = readReply(1, r.address);
        if (r.address == 1)
            bytes[bytes.size() - 2] = char(bytes.at(bytes.size() - 2) ^ 0x10);
        return reply(bytes);
    });
    ModbusResult r = f.backend->transact(ModbusRequest::readHolding(1, 1, 1), 200);
    EXPECT_EQ(r.error, ModbusError::CrcError);
    EXPECT_EQ(r.reply.size(), 7); // the whole rejected frame is kept for the log
    r = f.backend->transact(ModbusRequest::readHolding(1, 2, 1), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({2}));
}

TEST(RtuBackendTest, WrongSlaveAndItsSecondFrameAreDiscarded)
{
    // Two devices answer: id 2 first, then the addressed one a little later.
    RtuFixture f([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        Answer a = reply(readReply(r.address == 1 ? 2 : 1, r.address));
        if (r.address == 1) {
            a.second = readReply(1, 999);
            a.secondDelayMs = 3;
        }
        return a;
    });
    ModbusResult r = f.backend->transact(ModbusRequest::readHolding(1, 1, 1), 200);
    EXPECT_EQ(r.error, ModbusError::WrongSlave);
    EXPECT_TRUE(r.message.contains(QStringLiteral("slave 2")));
    const auto rx = f.entries(TrafficEntry::Direction::Rx);
    ASSERT_FALSE(rx.isEmpty());
    EXPECT_EQ(rx[0].slave, 2);
    r = f.backend->transact(ModbusRequest::readHolding(1, 5, 1), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({5}));
}

TEST(RtuBackendTest, MalformedAndIncompleteReplies)
{
    RtuFixture f([](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        if (r.address == 1) // byte count 4 for one register, CRC fine
            return reply(RtuFrame::encodeReadReply(1, 3, {1, 2}));
        if (r.address == 2) // stops after the first data byte
            return reply(readReply(1, 2).left(4));
        return reply(readReply(1, r.address));
    });
    ModbusResult r = f.backend->transact(ModbusRequest::readHolding(1, 1, 1), 200);
    EXPECT_EQ(r.error, ModbusError::MalformedReply);
    r = f.backend->transact(ModbusRequest::readHolding(1, 2, 1), 200);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    EXPECT_TRUE(r.message.contains(QStringLiteral("incomplete")));
    r = f.backend->transact(ModbusRequest::readHolding(1, 3, 1), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({3}));
}

TEST(RtuBackendTest, NoReplyTimesOut)
{
    RtuFixture f([](const QByteArray&) { return Answer(); });
    QElapsedTimer timer;
    timer.start();
    const ModbusResult r = f.backend->transact(ModbusRequest::readHolding(1, 0, 1), 100);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    EXPECT_GE(timer.elapsed(), 95);
    EXPECT_LT(timer.elapsed(), 400);
    const auto events = f.entries(TrafficEntry::Direction::Event);
    ASSERT_EQ(events.size(), 1);
    EXPECT_FALSE(events[0].error.isEmpty());
}

TEST(RtuBackendTest, LateReplyIsNotTakenForTheNextRequest)
{
    // At 1200 baud one 7-byte reply takes ~60 ms on a real line; the device answers 30 ms
    // after the client gave up. Both replies have the same shape, so only timing tells them
    // apart: the backend must drain the late one before sending again.
    RtuFixture f(
        [](const QByteArray& request) {
            ModbusRequest r;
            RtuFrame::decodeRequest(request, &r);
            return r.address == 0x100 ? reply(readReply(1, 1111), 130) : reply(readReply(1, 2222));
        },
        1200);
    ModbusResult r = f.backend->transact(ModbusRequest::readHolding(1, 0x100, 1), 100);
    EXPECT_EQ(r.error, ModbusError::Timeout);
    r = f.backend->transact(ModbusRequest::readHolding(1, 0x101, 1), 300);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({2222}));
    bool discarded = false;
    for (const TrafficEntry& e : f.entries(TrafficEntry::Direction::Rx))
        discarded |= e.error.contains(QStringLiteral("discarded")) && e.bytes == readReply(1, 1111);
    EXPECT_TRUE(discarded);
}

TEST(RtuBackendTest, DeviceIdentification)
{
    RtuFixture f([](const QByteArray& request) {
        const quint8 slave = quint8(request.at(0));
        if (slave == 1) { // the object list arrives in two pieces
            Answer a = reply(deviceIdReply(1).left(12));
            a.second = deviceIdReply(1).mid(12);
            a.secondDelayMs = 5;
            return a;
        }
        if (slave == 2)
            return reply(RtuFrame::encodeException(2, 0x2B, 0x01));
        if (slave == 3) {
            QByteArray bad = deviceIdReply(3);
            bad[bad.size() - 1] = char(bad.at(bad.size() - 1) ^ 1);
            return reply(bad);
        }
        if (slave == 4)
            return reply(deviceIdReply(5));
        return Answer();
    });
    ModbusResult r = f.backend->transact(ModbusRequest::readDeviceIdentification(1), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.reply, deviceIdReply(1));
    DeviceIdentification id;
    ASSERT_TRUE(DeviceIdentification::parse(r.rawData, &id));
    EXPECT_EQ(id.text(1), QStringLiteral("DCPID-20A"));
    const auto rx = f.entries(TrafficEntry::Direction::Rx);
    ASSERT_EQ(rx.size(), 1);
    EXPECT_TRUE(rx[0].summary.contains(QStringLiteral("DCPID-20A")));

    r = f.backend->transact(ModbusRequest::readDeviceIdentification(2), 200);
    EXPECT_EQ(r.error, ModbusError::Exception);
    EXPECT_EQ(r.exceptionCode, 0x01);
    EXPECT_EQ(f.backend->transact(ModbusRequest::readDeviceIdentification(3), 200).error,
              ModbusError::CrcError);
    EXPECT_EQ(f.backend->transact(ModbusRequest::readDeviceIdentification(4), 200).error,
              ModbusError::WrongSlave);
    EXPECT_EQ(f.backend->transact(ModbusRequest::readDeviceIdentification(6), 100).error,
              ModbusError::Timeout);
    // And the line is clean afterwards.
    r = f.backend->transact(ModbusRequest::readDeviceIdentification(1), 200);
    EXPECT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
}

TEST(RtuBackendTest, BroadcastSendsAndKeepsTheBusQuiet)
{
    RtuFixture f([](const QByteArray&) { return Answer(); });
    EXPECT_EQ(f.backend->turnaroundMs(), 10); // max(3.5 chars + 5 ms, 10 ms) at 19200
    f.backend->setTurnaroundMs(60);
    QElapsedTimer timer;
    timer.start();
    const ModbusResult r = f.backend->transact(ModbusRequest::writeSingle(0, 0x2000, 1), 1000);
    EXPECT_EQ(r.error, ModbusError::Ok);
    EXPECT_GE(timer.elapsed(), 60);
    EXPECT_LT(timer.elapsed(), 400); // did not wait for the 1 s timeout
    ASSERT_TRUE(waitUntil([&] { return f.device.requests().size() == 1; }));
    EXPECT_EQ(f.device.requests()[0],
              RtuFrame::encodeRequest(ModbusRequest::writeSingle(0, 0x2000, 1)));
    ConnectionSettings slow = ptySettings(f.device.path(), 1200);
    EXPECT_EQ(RtuBackend(slow).turnaroundMs(), 35); // 3.5 × 8.33 ms + 5 ms
}

// DBU manual 11-1: broadcasting gap T2 > C3.5 + 5 ms, with C3.5 = 4.0 ms at 9600 bit/s and
// 2.5 ms at 19200 bit/s. The quiet time after a broadcast keeps it at every rate, strictly.
TEST(RtuBackendTest, BroadcastGapIsLongerThanC35PlusFiveMs)
{
    const struct
    {
        int baud;
        double manualC35Ms; // the manual's figure where it gives one, else 3.5 characters
    } rates[] = {{9600, 4.0}, {14400, 0}, {19200, 2.5}, {28800, 0},
                 {38400, 0},  {57600, 0}, {115200, 0},  {1200, 0}};
    for (const auto& r : rates) {
        ConnectionSettings s = ptySettings(QStringLiteral("/dev/null"), r.baud);
        const double c35 = std::max(r.manualC35Ms, 3.5 * s.charTimeMs());
        EXPECT_GT(RtuBackend(s).turnaroundMs(), c35 + 5) << r.baud;
    }
    // Where 3.5 characters + 5 ms is a whole number of ms (10 bits at 1000 bit/s: 40 ms), the gap
    // is still longer.
    ConnectionSettings exact = ptySettings(QStringLiteral("/dev/null"), 1000);
    ASSERT_DOUBLE_EQ(3.5 * exact.charTimeMs() + 5, 40.0);
    EXPECT_EQ(RtuBackend(exact).turnaroundMs(), 41);
}

TEST(RtuBackendTest, VanishingPortIsAPortError)
{
    RtuFixture f([](const QByteArray&) { return Answer(); });
    std::thread unplug([&] {
        QThread::msleep(50);
        f.device.closeMaster();
    });
    QElapsedTimer timer;
    timer.start();
    const ModbusResult r = f.backend->transact(ModbusRequest::readHolding(1, 0, 1), 2000);
    unplug.join();
    EXPECT_EQ(r.error, ModbusError::PortError) << r.errorText().toStdString();
    EXPECT_LT(timer.elapsed(), 1000);
    EXPECT_FALSE(f.backend->isOpen());
    EXPECT_EQ(f.backend->transact(ModbusRequest::readHolding(1, 0, 1), 100).error,
              ModbusError::NotConnected);
}

TEST(RtuBackendTest, VanishingPortBetweenRequests)
{
    RtuFixture f([](const QByteArray&) { return reply(readReply(1, 1)); });
    ASSERT_EQ(f.backend->transact(ModbusRequest::readHolding(1, 0, 1), 200).error, ModbusError::Ok);
    f.device.closeMaster();
    EXPECT_EQ(f.backend->transact(ModbusRequest::readHolding(1, 0, 1), 200).error,
              ModbusError::PortError);
    EXPECT_FALSE(f.backend->isOpen());
}

TEST(RtuBackendTest, OpenFailureNamesThePort)
{
    ConnectionSettings s = ptySettings(QStringLiteral("/dev/opentop-no-such-port"));
    RtuBackend backend(s);
    QString error;
    EXPECT_FALSE(backend.open(&error));
    EXPECT_FALSE(backend.isOpen());
    EXPECT_TRUE(error.contains(QStringLiteral("/dev/opentop-no-such-port"))) << error.toStdString();
    EXPECT_EQ(backend.transact(ModbusRequest::readHolding(1, 0, 1), 100).error,
              ModbusError::NotConnected);
}

TEST(RtuBackendTest, SecondConnectionToTheSamePortIsRefused)
{
    RtuFixture f([](const QByteArray&) { return reply(readReply(1, 7)); });
    RtuBackend second(ptySettings(f.device.path()));
    QString error;
    EXPECT_FALSE(second.open(&error));
    EXPECT_TRUE(error.contains(QStringLiteral("in use"))) << error.toStdString();
    EXPECT_EQ(f.backend->transact(ModbusRequest::readHolding(1, 0, 1), 200).error, ModbusError::Ok);
    f.backend->close();
    EXPECT_TRUE(second.open(&error)) << error.toStdString();
    EXPECT_EQ(second.transact(ModbusRequest::readHolding(1, 0, 1), 200).registers,
              QVector<quint16>({7}));
}

TEST(RtuBackendTest, ClientReportsConnectionLost)
{
    PtyDevice device;
    device.start([](const QByteArray&) { return reply(readReply(1, 42)); });
    ModbusClient client(std::make_unique<RtuBackend>(ptySettings(device.path())),
                        ptySettings(device.path()));
    ASSERT_EQ(client.openBlocking(), QString());
    EXPECT_EQ(client.execute(ModbusRequest::readHolding(1, 0, 1)).registers,
              QVector<quint16>({42}));
    QString lost;
    QObject::connect(&client, &ModbusClient::connectionLost, [&](const QString& e) { lost = e; });
    device.closeMaster();
    EXPECT_EQ(client.execute(ModbusRequest::readHolding(1, 0, 1)).error, ModbusError::PortError);
    ASSERT_TRUE(waitUntil([&] { return !lost.isEmpty(); }));
    EXPECT_FALSE(client.isOpen());
}

TEST(RtuBackendTest, ClientDestructionClosesThePortWithinBound)
{
    PtyDevice device;
    device.start([](const QByteArray&) { return Answer(); });
    const int before = openDescriptorsOn(device.path());
    auto client = std::make_unique<ModbusClient>(
        std::make_unique<RtuBackend>(ptySettings(device.path())), ptySettings(device.path()));
    ASSERT_EQ(client->openBlocking(), QString());
    // The Modbus context's descriptor and the port lock's (PortLock).
    EXPECT_EQ(openDescriptorsOn(device.path()), before + 2);
    ModbusRequest slow = ModbusRequest::readHolding(1, 0, 1);
    slow.timeoutMs = 10000;
    client->submit(slow);
    ASSERT_TRUE(waitUntil([&] { return device.requests().size() == 1; }));
    QElapsedTimer timer;
    timer.start();
    client.reset();
    EXPECT_LT(timer.elapsed(), 2000);
    EXPECT_EQ(openDescriptorsOn(device.path()), before);
}
