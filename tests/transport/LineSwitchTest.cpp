// One port, drives of different line formats: a request carries its drive's format, the client
// keeps the per-drive table, and RtuBackend switches the port between transactions only. Over
// a real openpty() pair: the device thread reads the format the client's port is in with
// TCGETS on the master (Linux returns the slave's termios there), as opentop-sim does.
#include "tests/transport/TransportTestSupport.h"
#include "transport/IoctlSerialDriver.h"
#include "transport/LineFormat.h"
#include "transport/ModbusClient.h"
#include "transport/RtuBackend.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficLog.h"

#include <QElapsedTimer>
#include <atomic>
#include <chrono>
#include <gtest/gtest.h>
#include <mutex>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <thread>
#include <unistd.h>

using namespace opentop;
using namespace opentop::test;

namespace {

double nowMs()
{
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

LineFormat fmt(const char* text, int baud)
{
    return LineFormat::parse(QString::fromLatin1(text), baud).value();
}

// A device on the master side of a pty: answers every read with one register, and notes for
// each request the client's format and when its first byte came; for each reply when it went.
class FormatDevice
{
public:
    struct Seen
    {
        QByteArray request;
        LineFormat format;
        double arrivedMs = 0;
        double repliedMs = 0; // when the reply was written (a pty passes it on at once)
    };

    FormatDevice()
    {
        char name[256] = {};
        EXPECT_EQ(::openpty(&m_master, &m_slave, name, nullptr, nullptr), 0);
        termios tio{};
        ::tcgetattr(m_slave, &tio);
        ::cfmakeraw(&tio);
        ::tcsetattr(m_slave, TCSANOW, &tio);
        m_path = QString::fromLocal8Bit(name);
        m_thread = std::thread([this] { run(); });
    }
    ~FormatDevice()
    {
        m_stop = true;
        m_thread.join();
        ::close(m_master);
        ::close(m_slave);
    }
    QString path() const { return m_path; }
    std::vector<Seen> seen() const
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_seen;
    }

private:
    void run()
    {
        QByteArray buffer;
        Seen current;
        while (!m_stop) {
            pollfd pfd{m_master, POLLIN, 0};
            if (::poll(&pfd, 1, 10) <= 0)
                continue;
            if (buffer.isEmpty()) {
                current.arrivedMs = nowMs();
                current.format = IoctlSerialDriver::formatOf(m_master);
            }
            char chunk[256];
            const ssize_t n = ::read(m_master, chunk, sizeof chunk);
            if (n <= 0)
                continue;
            buffer.append(chunk, int(n));
            if (buffer.size() < 8)
                continue;
            current.request = buffer.left(8);
            buffer.remove(0, 8);
            QByteArray reply;
            if (current.request.at(0) != 0) {
                reply = RtuFrame::encodeReadReply(quint8(current.request.at(0)), 0x03, {1234});
                // Noted before the write: a thread preempted after writing would note a time
                // later than the client saw the reply.
                current.repliedMs = nowMs();
            }
            {
                // Also before the write: the client may finish and the test read seen() before
                // this thread runs again.
                std::lock_guard<std::mutex> lock(m_mutex);
                m_seen.push_back(current);
            }
            if (!reply.isEmpty()) {
                EXPECT_EQ(::write(m_master, reply.constData(), size_t(reply.size())), reply.size());
            }
        }
    }

    int m_master = -1;
    int m_slave = -1;
    QString m_path;
    std::thread m_thread;
    std::atomic<bool> m_stop{false};
    mutable std::mutex m_mutex;
    std::vector<Seen> m_seen;
};

ConnectionSettings portAt(const QString& path)
{
    ConnectionSettings s;
    s.port = path;
    s.baud = 19200; // 8N1: a DBU bus
    s.timeoutMs = 300;
    return s;
}

// Every driver call goes to the real port; the time of each is noted, so that the test sees
// that the switch waits for the line.
class TimedDriver : public SerialDriver
{
public:
    TimedDriver(std::unique_ptr<SerialDriver> real, std::vector<std::pair<QString, double>>* calls)
        : m_real(std::move(real))
        , m_calls(calls)
    {
    }
    int getRs485(Rs485* s) override { return m_real->getRs485(s); }
    int setRs485(Rs485* s) override { return m_real->setRs485(s); }
    int useRts(bool h, int d, Rts* r) override { return m_real->useRts(h, d, r); }
    int getLowLatency(bool* on) override { return m_real->getLowLatency(on); }
    int setLowLatency(bool on) override { return m_real->setLowLatency(on); }
    int drainOutput() override
    {
        m_calls->emplace_back(QStringLiteral("drain"), nowMs());
        return m_real->drainOutput();
    }
    int setFormat(const LineFormat& f, LineFormat* readBack) override
    {
        m_calls->emplace_back(QStringLiteral("set ") + f.text(), nowMs());
        return m_real->setFormat(f, readBack);
    }

private:
    std::unique_ptr<SerialDriver> m_real;
    std::vector<std::pair<QString, double>>* m_calls;
};

class TimedRtuBackend : public RtuBackend
{
public:
    using RtuBackend::RtuBackend;
    std::vector<std::pair<QString, double>> calls;

protected:
    std::unique_ptr<SerialDriver> makeDriver() override
    {
        return std::make_unique<TimedDriver>(RtuBackend::makeDriver(), &calls);
    }
};

ModbusRequest readAt(quint8 slave, const LineFormat& line = LineFormat())
{
    ModbusRequest r = ModbusRequest::readHolding(slave, 0x0010, 1);
    r.line = line;
    return r;
}

} // namespace

TEST(LineFormat, ParsesTheFormsUsersWrite)
{
    EXPECT_EQ(fmt("8E1", 9600), (LineFormat{9600, 'E', 8, 1}));
    EXPECT_EQ(LineFormat::parse(QStringLiteral("9600:8e1"), 19200).value(),
              (LineFormat{9600, 'E', 8, 1}));
    EXPECT_EQ(LineFormat::parse(QStringLiteral("19200 8N2"), 9600).value(),
              (LineFormat{19200, 'N', 8, 2}));
    EXPECT_EQ(LineFormat::parse(QStringLiteral("8O1@38400"), 9600).value(),
              (LineFormat{38400, 'O', 8, 1}));
    QString error;
    EXPECT_FALSE(LineFormat::parse(QStringLiteral("8X1"), 9600, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("8N1"))) << error.toStdString();
    EXPECT_FALSE(LineFormat::parse(QStringLiteral("300:8N1"), 9600, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("1200–115200"))) << error.toStdString();
    EXPECT_EQ(fmt("8E1", 9600).token(), QStringLiteral("9600:8E1"));
    EXPECT_EQ(fmt("8E1", 9600).text(), QStringLiteral("9600 8E1"));
}

TEST(LineFormat, TableOfDrives)
{
    const auto table = LineFormat::parseTable(QStringLiteral("7=9600:8E1, 9=8N2"), 19200);
    ASSERT_TRUE(table);
    EXPECT_EQ(table->value(7), (LineFormat{9600, 'E', 8, 1}));
    EXPECT_EQ(table->value(9), (LineFormat{19200, 'N', 8, 2}));
    EXPECT_EQ(LineFormat::tableText(*table), QStringLiteral("7=9600:8E1,9=19200:8N2"));
    QString error;
    EXPECT_FALSE(LineFormat::parseTable(QStringLiteral("300=8E1"), 19200, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("1–247"))) << error.toStdString();
    EXPECT_FALSE(LineFormat::parseTable(QStringLiteral("7=9600"), 19200, &error));
}

TEST(LineFormat, AReceiverChecksRateDataBitsAndParityNotTheSecondStopBit)
{
    const LineFormat dbu{19200, 'N', 8, 1};
    EXPECT_TRUE(LineFormat({19200, 'N', 8, 2}).hears(dbu)); // a DC controller at 8N2 joins
    EXPECT_TRUE(dbu.hears({19200, 'N', 8, 2}));
    EXPECT_FALSE(LineFormat({19200, 'E', 8, 1}).hears(dbu));
    EXPECT_FALSE(LineFormat({9600, 'N', 8, 1}).hears(dbu));
    EXPECT_FALSE(LineFormat({19200, 'O', 8, 1}).hears({19200, 'E', 8, 1}));
}

TEST(LineSwitchClient, RequestsCarryTheirDrivesFormatAndBroadcastsGoOutInEach)
{
    ConnectionSettings port;
    port.baud = 19200;
    MockClient c(echoDevice, port);
    const LineFormat dc{9600, 'E', 8, 1};
    c.client->setDriveLine(7, dc);
    EXPECT_TRUE(c.client->hasOwnLine(7));
    EXPECT_EQ(c.client->driveLine(7), dc);
    EXPECT_EQ(c.client->driveLine(1), port.line());
    EXPECT_TRUE(c.client->execute(ModbusRequest::readHolding(7, 0x10, 1)).ok());
    EXPECT_TRUE(c.client->execute(ModbusRequest::readHolding(1, 0x10, 1)).ok());
    // A broadcast reaches a drive only in its format: once in the port's, once in 9600 8E1.
    EXPECT_TRUE(c.client->execute(ModbusRequest::writeSingle(0, 0x2003, 0)).ok());
    // Back at the port's: the entry goes.
    c.client->setDriveLine(7, port.line());
    EXPECT_FALSE(c.client->hasOwnLine(7));
    EXPECT_TRUE(c.client->execute(ModbusRequest::readHolding(7, 0x10, 1)).ok());

    const QVector<LineFormat> lines = c.mock->lines();
    ASSERT_EQ(lines.size(), 5);
    EXPECT_EQ(lines[0], dc);
    EXPECT_FALSE(lines[1].isSet());
    EXPECT_FALSE(lines[2].isSet());
    EXPECT_EQ(lines[3], dc);
    EXPECT_FALSE(lines[4].isSet());
}

TEST(LineSwitchClient, ABroadcastIsNotRepeatedForAFormatThePortsAlreadyReaches)
{
    ConnectionSettings port;
    port.baud = 19200;
    MockClient c(echoDevice, port);
    c.client->setDriveLine(7, {19200, 'N', 8, 2}); // an 8N2 drive hears 8N1
    EXPECT_TRUE(c.client->execute(ModbusRequest::writeSingle(0, 0x2003, 0)).ok());
    EXPECT_EQ(c.mock->requestCount(), 1);
}

TEST(LineSwitchRtu, TheFormatARequestCarriesReachesThePort)
{
    // What is checked is the format, not the timing: a long wait for a busy machine.
    constexpr int kWait = 3000;
    FormatDevice device;
    RtuBackend backend(portAt(device.path()));
    TrafficLog log;
    backend.setTrafficLog(&log);
    QString error;
    ASSERT_TRUE(backend.open(&error)) << error.toStdString();
    EXPECT_TRUE(backend.transact(readAt(1), kWait).ok());
    EXPECT_TRUE(backend.transact(readAt(7, fmt("8E1", 9600)), kWait).ok());
    EXPECT_TRUE(backend.transact(readAt(8, fmt("8O1", 9600)), kWait).ok());
    EXPECT_TRUE(backend.transact(readAt(9, fmt("8N2", 38400)), kWait).ok());
    EXPECT_TRUE(backend.transact(readAt(1), kWait).ok());
    EXPECT_EQ(backend.lineSwitches(), 4);
    backend.close();
    // The traffic log names the format of every frame sent in another than the port's.
    QStringList sent;
    for (const TrafficEntry& e : log.entries())
        if (e.direction == TrafficEntry::Direction::Tx)
            sent << e.summary;
    ASSERT_EQ(sent.size(), 5);
    EXPECT_FALSE(sent[0].contains(QLatin1Char('[')));
    EXPECT_TRUE(sent[1].endsWith(QStringLiteral("[9600 8E1]"))) << sent[1].toStdString();
    EXPECT_TRUE(sent[3].endsWith(QStringLiteral("[38400 8N2]"))) << sent[3].toStdString();
    EXPECT_FALSE(sent[4].contains(QLatin1Char('[')));

    const auto seen = device.seen();
    ASSERT_EQ(seen.size(), 5u);
    EXPECT_EQ(seen[0].format, (LineFormat{19200, 'N', 8, 1}));
    // A pty drops PARENB but keeps INPCK and PARODD: the format as the master set it.
    EXPECT_EQ(seen[1].format, (LineFormat{9600, 'E', 8, 1}));
    EXPECT_EQ(seen[2].format, (LineFormat{9600, 'O', 8, 1}));
    EXPECT_EQ(seen[3].format, (LineFormat{38400, 'N', 8, 2}));
    EXPECT_EQ(seen[4].format, (LineFormat{19200, 'N', 8, 1}));
}

TEST(LineSwitchRtu, ASwitchWaitsForTheLineAndKeepsTheGapAtTheNewRate)
{
    FormatDevice device;
    TimedRtuBackend backend(portAt(device.path()));
    QString error;
    ASSERT_TRUE(backend.open(&error)) << error.toStdString();
    backend.calls.clear();
    const LineFormat dc = fmt("8E1", 9600);
    for (int i = 0; i < 10; ++i) {
        ASSERT_TRUE(backend.transact(readAt(1), 300).ok());
        ASSERT_TRUE(backend.transact(readAt(7, dc), 300).ok());
    }
    const double meanUs = backend.meanSwitchMicros();
    backend.close();

    const auto seen = device.seen();
    ASSERT_EQ(seen.size(), 20u);
    ASSERT_EQ(backend.calls.size(), 2u * 19);        // drain + set per switch; the first needs none
    const double oldGapMs = 3.5 * 10 * 1000 / 19200; // 8N1 at 19200: 1.82 ms
    const double newGapMs = 3.5 * 11 * 1000 / 9600;  // 8E1 at 9600: 4.01 ms
    for (int i = 1; i < 20; ++i) {
        const auto& drain = backend.calls[size_t(2 * (i - 1))];
        const auto& set = backend.calls[size_t(2 * (i - 1) + 1)];
        EXPECT_EQ(drain.first, QStringLiteral("drain"));
        EXPECT_EQ(set.first,
                  QStringLiteral("set ") + (i % 2 ? dc.text() : QStringLiteral("19200 8N1")));
        // The previous reply was on the line and its gap kept before the port changed.
        EXPECT_GE(drain.second - seen[size_t(i - 1)].repliedMs, oldGapMs) << i;
        EXPECT_LE(drain.second, set.second);
        // The next request keeps the gap of its own format after the last frame.
        const double gap = i % 2 ? std::max(oldGapMs, newGapMs) : oldGapMs;
        EXPECT_GE(seen[size_t(i)].arrivedMs - seen[size_t(i - 1)].repliedMs, gap) << i;
        EXPECT_EQ(seen[size_t(i)].format, i % 2 ? dc : (LineFormat{19200, 'N', 8, 1})) << i;
    }
    // The cost of a switch on this machine's pty (tcdrain + tcsetattr), for docs/communication.md.
    RecordProperty("meanSwitchMicros", int(meanUs));
    std::printf("mean line switch on a pty: %.0f us\n", meanUs);
    EXPECT_GT(meanUs, 0);
}

TEST(LineSwitchRtu, AFormatThePortCannotTakeFailsThatRequestAndKeepsTheLine)
{
    FormatDevice device;
    RtuBackend backend(portAt(device.path()));
    QString error;
    ASSERT_TRUE(backend.open(&error)) << error.toStdString();
    const ModbusResult odd = backend.transact(readAt(7, fmt("8N1", 14400)), 300);
    EXPECT_EQ(odd.error, ModbusError::PortError);
    EXPECT_TRUE(odd.message.contains(QStringLiteral("14400 8N1"))) << odd.message.toStdString();
    EXPECT_TRUE(backend.isOpen());
    EXPECT_TRUE(backend.transact(readAt(1), 300).ok());
    ASSERT_EQ(device.seen().size(), 1u);
    EXPECT_EQ(device.seen()[0].format, (LineFormat{19200, 'N', 8, 1}));
}
