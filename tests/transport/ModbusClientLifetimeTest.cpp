// ModbusClient opening, losing and closing its connection, and bounded destruction.
#include "tests/transport/TransportTestSupport.h"
#include "transport/MockBackend.h"
#include "transport/ModbusClient.h"

#include <QElapsedTimer>
#include <QThread>
#include <gtest/gtest.h>

using namespace opentop;
using opentop::test::echoDevice;
using opentop::test::MockClient;
using opentop::test::waitUntil;

TEST(ModbusClientLifetimeTest, NotOpenAndOpenFailure)
{
    MockClient closed(echoDevice, ConnectionSettings(), false);
    EXPECT_EQ(closed.client->execute(ModbusRequest::readHolding(1, 0, 1)).error,
              ModbusError::NotConnected);
    EXPECT_EQ(closed.mock->requestCount(), 0);

    closed.mock->setOpenError(QStringLiteral("no such port"));
    EXPECT_EQ(closed.client->openBlocking(), QStringLiteral("no such port"));
    bool reported = false;
    QString error;
    QObject::connect(closed.client.get(), &ModbusClient::opened, [&](bool ok, const QString& e) {
        reported = !ok;
        error = e;
    });
    closed.client->open();
    ASSERT_TRUE(waitUntil([&] { return reported; }));
    EXPECT_EQ(error, QStringLiteral("no such port"));
    EXPECT_FALSE(closed.client->isOpen());
}

TEST(ModbusClientLifetimeTest, PortErrorEmitsConnectionLostOnce)
{
    MockClient f(echoDevice);
    int lost = 0;
    QString why;
    QObject::connect(f.client.get(), &ModbusClient::connectionLost, [&](const QString& e) {
        ++lost;
        why = e;
    });
    f.mock->failPort(QStringLiteral("adapter unplugged"));
    EXPECT_EQ(f.client->execute(ModbusRequest::readHolding(1, 0, 1)).error, ModbusError::PortError);
    EXPECT_FALSE(f.client->isOpen());
    EXPECT_EQ(f.client->execute(ModbusRequest::readHolding(1, 0, 1)).error,
              ModbusError::NotConnected);
    ASSERT_TRUE(waitUntil([&] { return lost > 0; }));
    waitUntil([] { return false; }, 50);
    EXPECT_EQ(lost, 1);
    EXPECT_EQ(why, QStringLiteral("adapter unplugged"));
    // Reopening works and re-arms the notification.
    EXPECT_EQ(f.client->openBlocking(), QString());
    EXPECT_EQ(f.client->execute(ModbusRequest::readHolding(1, 3, 1)).error, ModbusError::Ok);
}

TEST(ModbusClientLifetimeTest, DestructionInterruptsAWaitingRequest)
{
    MockClient f([](const QByteArray&) { return QByteArray(); });
    f.mock->setNoReplyDelayMs(10000);
    ModbusRequest slow = ModbusRequest::readHolding(1, 0, 1);
    slow.timeoutMs = 10000;
    bool called = false;
    f.client->submit(slow, nullptr, [&](const ModbusResult&) { called = true; });
    f.client->submit(ModbusRequest::readHolding(1, 1, 1));
    ASSERT_TRUE(waitUntil([&] { return f.mock->requestCount() == 1; }));
    QElapsedTimer timer;
    timer.start();
    f.client.reset();
    EXPECT_LT(timer.elapsed(), 1000); // interrupted, not the 1.5 s fallback
    waitUntil([] { return false; }, 20);
    EXPECT_FALSE(called); // nothing is delivered once the client is gone
}

TEST(ModbusClientLifetimeTest, DestructionIsBoundedEvenIfTheBackendIsStuck)
{
    // A handler that ignores the interrupt, like a blocking connect.
    auto done = std::make_shared<std::atomic<bool>>(false);
    MockClient f([done](const QByteArray&) {
        QThread::msleep(1800);
        *done = true;
        return QByteArray();
    });
    f.client->submit(ModbusRequest::readHolding(1, 0, 1));
    ASSERT_TRUE(waitUntil([&] { return f.mock->requestCount() == 1; }));
    QElapsedTimer timer;
    timer.start();
    f.client.reset();
    EXPECT_LT(timer.elapsed(), 2000);
    // Let the detached worker finish before the next test.
    ASSERT_TRUE(waitUntil([&] { return done->load(); }, 3000));
    QThread::msleep(20);
}
