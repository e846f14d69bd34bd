// LinkRecovery (model/bus/): a client whose port failed is opened again by itself, the waits
// between attempts doubling up to their limit, until the port is back or the limit to give up
// passes. A ModbusClient on a MockBackend whose port fails and whose opens are refused.
#include "model/bus/LinkRecovery.h"
#include "transport/MockBackend.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>
#include <QVector>
#include <functional>
#include <gtest/gtest.h>
#include <memory>

using namespace opentop;

namespace {

bool waitUntil(const std::function<bool()>& done, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (!done() && timer.elapsed() < timeoutMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        QThread::msleep(1);
    }
    return done();
}

// A client on an open MockBackend; `mock` lives as long as `client`.
struct Bus
{
    MockBackend* mock = nullptr;
    std::unique_ptr<ModbusClient> client;

    Bus()
    {
        auto backend =
            std::make_unique<MockBackend>([](const QByteArray&) { return QByteArray(); });
        mock = backend.get();
        client = std::make_unique<ModbusClient>(std::move(backend), ConnectionSettings());
        EXPECT_EQ(client->openBlocking(), QString());
    }

    // The adapter goes: the next request fails with a port error, and opens are refused.
    void pullOut()
    {
        mock->setOpenError(QStringLiteral("no such port"));
        mock->failPort(QStringLiteral("adapter unplugged"));
        client->submit(ModbusRequest::readHolding(1, 0, 1));
    }
};

} // namespace

TEST(LinkRecoveryTest, WaitsLongerEachTimeUpToItsLimitAndSaysWhenThePortIsBack)
{
    Bus bus;
    LinkRecovery recovery(bus.client.get());
    recovery.setDelays(20, 40);
    int lost = 0;
    QString why;
    QVector<qint64> attempts; // ms after the loss, of each refused open
    QElapsedTimer sinceLoss;
    qint64 backAfter = -1;
    QObject::connect(&recovery, &LinkRecovery::lost, [&](const QDateTime& at, const QString& w) {
        ++lost;
        why = w;
        sinceLoss.start();
        EXPECT_LE(qAbs(at.msecsTo(QDateTime::currentDateTime())), 1000);
    });
    QObject::connect(bus.client.get(), &ModbusClient::opened, [&](bool ok, const QString&) {
        if (!ok)
            attempts << sinceLoss.elapsed();
    });
    QObject::connect(&recovery, &LinkRecovery::back, [&](qint64 ms) { backAfter = ms; });

    bus.pullOut();
    ASSERT_TRUE(waitUntil([&] { return attempts.size() >= 10; }, 3000))
        << attempts.size() << " attempts; without a limit the tenth would come after 20 s";
    EXPECT_EQ(lost, 1);
    EXPECT_EQ(why, QStringLiteral("adapter unplugged"));
    EXPECT_TRUE(recovery.isLost());
    EXPECT_FALSE(bus.client->isOpen());
    EXPECT_EQ(recovery.lastError(), QStringLiteral("no such port"));
    // 20 ms, then 40 ms apart (a timer may fire a little early, never much).
    EXPECT_GE(attempts[0], 18);
    for (int i = 1; i < attempts.size(); ++i)
        EXPECT_GE(attempts[i] - attempts[i - 1], 36) << "attempt " << i;

    // The adapter plugged in again: the next attempt opens it.
    bus.mock->setOpenError(QString());
    ASSERT_TRUE(waitUntil([&] { return backAfter >= 0; }, 2000));
    EXPECT_GE(backAfter, attempts.last());
    EXPECT_FALSE(recovery.isLost());
    EXPECT_TRUE(bus.client->isOpen());
    EXPECT_EQ(recovery.lostForMs(), 0);
    EXPECT_EQ(bus.client->execute(ModbusRequest::readHolding(1, 0, 1)).error,
              ModbusError::Timeout); // on the wire again: the mock's device stays silent

    // Lost again: said again, and recovered again from the first wait.
    bus.pullOut();
    ASSERT_TRUE(waitUntil([&] { return lost == 2; }, 2000));
    EXPECT_TRUE(recovery.isLost());
}

TEST(LinkRecoveryTest, GivesUpOnceTheLossHasLastedItsLimit)
{
    Bus bus;
    LinkRecovery recovery(bus.client.get());
    recovery.setDelays(20, 40);
    recovery.setGiveUpMs(300);
    int gaveUp = 0;
    qint64 gaveUpAfter = 0;
    QString lastError;
    bool back = false;
    QObject::connect(&recovery, &LinkRecovery::gaveUp, [&](qint64 ms, const QString& e) {
        ++gaveUp;
        gaveUpAfter = ms;
        lastError = e;
    });
    QObject::connect(&recovery, &LinkRecovery::back, [&] { back = true; });
    bus.pullOut();
    ASSERT_TRUE(waitUntil([&] { return gaveUp > 0; }, 3000));
    EXPECT_GE(gaveUpAfter, 285);
    EXPECT_LT(gaveUpAfter, 2000);
    EXPECT_EQ(lastError, QStringLiteral("no such port"));
    EXPECT_TRUE(recovery.isLost());
    const int attempts = recovery.attempts();
    EXPECT_GE(attempts, 2);

    // Given up: no more attempts, also once the port is back.
    bus.mock->setOpenError(QString());
    waitUntil([] { return false; }, 200);
    EXPECT_EQ(recovery.attempts(), attempts);
    EXPECT_FALSE(back);
    EXPECT_FALSE(bus.client->isOpen());
    EXPECT_EQ(gaveUp, 1);
}

TEST(LinkRecoveryTest, AnOpenNotItsOwnIsNoReturnAndMarkLostIsSaidOnce)
{
    Bus bus;
    LinkRecovery recovery(bus.client.get());
    recovery.setDelays(10000, 10000); // no attempt of its own within the test
    int lost = 0;
    bool back = false;
    QObject::connect(&recovery, &LinkRecovery::lost, [&] { ++lost; });
    QObject::connect(&recovery, &LinkRecovery::back, [&] { back = true; });
    // The first open's opened() comes after the recovery was made: not a return.
    waitUntil([] { return false; }, 50);
    EXPECT_FALSE(back);
    recovery.markLost(QStringLiteral("mock is not open"));
    recovery.markLost(QStringLiteral("mock is not open"));
    EXPECT_EQ(lost, 1);
    EXPECT_EQ(recovery.lastError(), QStringLiteral("mock is not open"));
    // Someone else opening the client is not an attempt of the recovery's.
    bool opened = false;
    QObject::connect(bus.client.get(), &ModbusClient::opened, [&] { opened = true; });
    bus.client->open();
    ASSERT_TRUE(waitUntil([&] { return opened; }, 2000));
    EXPECT_FALSE(back);
    EXPECT_EQ(recovery.attempts(), 0);
}
