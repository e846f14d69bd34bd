#include "transport/TrafficLog.h"
#include "transport/ModbusRequest.h"

#include <gtest/gtest.h>
#include <thread>

using namespace opentop;

namespace {

TrafficEntry entry(const char* summary)
{
    TrafficEntry e;
    e.direction = TrafficEntry::Direction::Tx;
    e.slave = 1;
    e.function = 3;
    e.bytes = QByteArray("\x01\x03", 2);
    e.summary = QString::fromUtf8(summary);
    return e;
}

} // namespace

TEST(TrafficLogTest, CapacityAndSequence)
{
    TrafficLog log(3);
    for (int i = 0; i < 5; ++i)
        log.append(entry("x"));
    const auto entries = log.entries();
    ASSERT_EQ(entries.size(), 3);
    EXPECT_EQ(entries.front().sequence, 3u); // oldest dropped, numbering continues
    EXPECT_EQ(entries.back().sequence, 5u);
    EXPECT_TRUE(entries.back().time.isValid());
    log.clear();
    EXPECT_TRUE(log.entries().isEmpty());
}

TEST(TrafficLogTest, DescriberSinkAndSignal)
{
    TrafficLog log;
    int signalled = 0;
    QObject::connect(&log, &TrafficLog::entryAdded, [&signalled] { ++signalled; });
    QStringList sunk;
    log.setSink([&sunk](const TrafficEntry& e) { sunk << e.summary; });
    log.setDescriber([](const TrafficEntry& e, const ModbusRequest* request) {
        if (!request)
            return QString();
        return e.summary + QStringLiteral(" (speed 1)");
    });
    const ModbusRequest request = ModbusRequest::readHolding(1, 0xCA03, 1);
    log.append(entry("read 03 0xCA03 ×1"), &request);
    log.append(entry("plain"));
    EXPECT_EQ(sunk, QStringList(
                        {QStringLiteral("read 03 0xCA03 ×1 (speed 1)"), QStringLiteral("plain")}));
    EXPECT_EQ(signalled, 2);
    const QString line = log.entries().front().toLine();
    EXPECT_TRUE(line.contains(QStringLiteral("TX #1 01 03  read 03 0xCA03 ×1 (speed 1)")))
        << line.toStdString();
}

TEST(TrafficLogTest, ConcurrentAppendsKeepEveryEntry)
{
    TrafficLog log(100000);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&log] {
            for (int i = 0; i < 500; ++i)
                log.append(entry("x"));
        });
    for (auto& thread : threads)
        thread.join();
    const auto entries = log.entries();
    ASSERT_EQ(entries.size(), 2000);
    for (int i = 0; i < entries.size(); ++i)
        EXPECT_EQ(entries[i].sequence, quint64(i + 1));
}
