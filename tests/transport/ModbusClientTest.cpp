#include "transport/ModbusClient.h"
#include "tests/transport/TransportTestSupport.h"
#include "transport/MockBackend.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficLog.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>
#include <condition_variable>
#include <gtest/gtest.h>
#include <mutex>

using namespace opentop;
using opentop::test::echoDevice;
using opentop::test::MockClient;
using opentop::test::waitUntil;

namespace {

quint16 addressOf(const QByteArray& adu)
{
    return quint16((quint8(adu.at(2)) << 8) | quint8(adu.at(3)));
}

// Holds the device on its first request until the test releases it.
struct Gate
{
    std::mutex mutex;
    std::condition_variable cv;
    bool released = false;
    std::atomic<int> entered{0};

    void pass()
    {
        ++entered;
        std::unique_lock<std::mutex> lock(mutex);
        cv.wait(lock, [this] { return released; });
    }
    void release()
    {
        {
            std::lock_guard<std::mutex> lock(mutex);
            released = true;
        }
        cv.notify_all();
    }
};

} // namespace

TEST(ModbusClientTest, ExecuteGoesThroughTheWorker)
{
    TrafficLog log;
    auto backend = std::make_unique<MockBackend>(echoDevice);
    MockBackend* mock = backend.get();
    mock->setTrafficLog(&log);
    ModbusClient client(std::move(backend), ConnectionSettings());
    ASSERT_EQ(client.openBlocking(), QString());
    EXPECT_TRUE(client.isOpen());
    const ModbusResult r = client.execute(ModbusRequest::readHolding(1, 10, 2));
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({10, 11}));
    EXPECT_EQ(r.attempts, 1);
    ASSERT_EQ(mock->requestCount(), 1);
    EXPECT_EQ(mock->requests().front(),
              RtuFrame::encodeRequest(ModbusRequest::readHolding(1, 10, 2)));
    const auto entries = log.entries();
    ASSERT_EQ(entries.size(), 2);
    EXPECT_EQ(entries[0].direction, TrafficEntry::Direction::Tx);
    EXPECT_EQ(entries[0].bytes, mock->requests().front());
    EXPECT_EQ(entries[1].direction, TrafficEntry::Direction::Rx);
    EXPECT_EQ(entries[1].summary, QStringLiteral("→ 10, 11"));
}

TEST(ModbusClientTest, UserBeforeNormalBeforePollThenFifo)
{
    auto gate = std::make_shared<Gate>();
    MockClient f([gate](const QByteArray& adu) {
        if (gate->entered == 0)
            gate->pass();
        return echoDevice(adu);
    });
    auto submit = [&f](quint16 address, ModbusRequest::Priority priority) {
        ModbusRequest r = ModbusRequest::readHolding(1, address, 1);
        r.priority = priority;
        return f.client->submit(r);
    };
    using P = ModbusRequest::Priority;
    submit(1, P::Poll); // on the wire, held by the gate
    ASSERT_TRUE(waitUntil([&] { return gate->entered == 1; }));
    submit(2, P::Poll);
    submit(3, P::Normal);
    submit(4, P::User);
    submit(5, P::Normal);
    submit(6, P::User);
    submit(7, P::Poll);
    EXPECT_EQ(f.client->pendingCount(), 7);
    int finished = 0;
    QObject::connect(f.client.get(), &ModbusClient::finished, [&finished] { ++finished; });
    gate->release();
    ASSERT_TRUE(waitUntil([&] { return finished == 7; }));
    QVector<quint16> order;
    for (const QByteArray& adu : f.mock->requests())
        order << addressOf(adu);
    EXPECT_EQ(order, QVector<quint16>({1, 4, 6, 3, 5, 2, 7}));
    EXPECT_EQ(f.client->pendingCount(), 0);
}

TEST(ModbusClientTest, PollsWaitWhileTheBusIsHeldAndOtherRequestsGoOn)
{
    // A scan holds the bus: the poll queued before and the one queued during the hold stay in
    // the queue, a user's request and a write still go, and the polls follow, in order, once
    // the last of two nested holds is released.
    MockClient f(echoDevice);
    QVector<bool> heldChanges;
    QObject::connect(f.client.get(), &ModbusClient::pollingHeldChanged,
                     [&heldChanges](bool held) { heldChanges << held; });
    f.client->holdPolling();
    f.client->holdPolling();
    EXPECT_TRUE(f.client->isPollingHeld());
    int finished = 0;
    QObject::connect(f.client.get(), &ModbusClient::finished, [&finished] { ++finished; });
    auto submit = [&f](quint16 address, ModbusRequest::Priority priority) {
        ModbusRequest r = ModbusRequest::readHolding(1, address, 1);
        r.priority = priority;
        return f.client->submit(r);
    };
    using P = ModbusRequest::Priority;
    submit(1, P::Poll);
    submit(2, P::User);
    submit(3, P::Poll);
    submit(4, P::Normal);
    ASSERT_TRUE(waitUntil([&] { return finished == 2; }));
    waitUntil([] { return false; }, 100); // the polls stay queued
    EXPECT_EQ(finished, 2);
    EXPECT_EQ(f.client->pendingCount(), 2);
    f.client->releasePolling(); // one hold is left
    waitUntil([] { return false; }, 100);
    EXPECT_EQ(finished, 2);
    f.client->releasePolling();
    EXPECT_FALSE(f.client->isPollingHeld());
    ASSERT_TRUE(waitUntil([&] { return finished == 4; }));
    QVector<quint16> order;
    for (const QByteArray& adu : f.mock->requests())
        order << addressOf(adu);
    EXPECT_EQ(order, QVector<quint16>({2, 4, 1, 3}));
    EXPECT_EQ(heldChanges, QVector<bool>({true, false}));
    // A release without a hold changes nothing.
    f.client->releasePolling();
    EXPECT_FALSE(f.client->isPollingHeld());
    EXPECT_EQ(heldChanges.size(), 2);
}

TEST(ModbusClientTest, CancelRemovesOnlyQueuedRequests)
{
    auto gate = std::make_shared<Gate>();
    MockClient f([gate](const QByteArray& adu) {
        if (gate->entered == 0)
            gate->pass();
        return echoDevice(adu);
    });
    QMap<quint16, ModbusResult> results;
    auto submit = [&](quint16 address) {
        return f.client->submit(
            ModbusRequest::readHolding(1, address, 1), f.client.get(),
            [&results, address](const ModbusResult& r) { results[address] = r; });
    };
    const auto a = submit(1);
    ASSERT_TRUE(waitUntil([&] { return gate->entered == 1; }));
    const auto b = submit(2);
    submit(3);
    submit(4);
    submit(5);
    EXPECT_FALSE(f.client->cancel(a)); // on the wire: it completes
    EXPECT_TRUE(f.client->cancel(b));
    EXPECT_FALSE(f.client->cancel(b));
    EXPECT_FALSE(f.client->cancel(12345));
    EXPECT_EQ(f.client->pendingCount(), 4);
    ASSERT_TRUE(waitUntil([&] { return results.contains(2); }));
    EXPECT_EQ(results[2].error, ModbusError::Cancelled);
    EXPECT_EQ(results[2].attempts, 0);
    gate->release();
    ASSERT_TRUE(waitUntil([&] { return results.size() == 5; }));
    EXPECT_EQ(results[1].error, ModbusError::Ok);
    EXPECT_EQ(results[3].error, ModbusError::Ok);
    QVector<quint16> sent;
    for (const QByteArray& adu : f.mock->requests())
        sent << addressOf(adu);
    EXPECT_EQ(sent, QVector<quint16>({1, 3, 4, 5}));
}

TEST(ModbusClientTest, CancelAllDeliversCancelled)
{
    auto gate = std::make_shared<Gate>();
    MockClient f([gate](const QByteArray& adu) {
        if (gate->entered == 0)
            gate->pass();
        return echoDevice(adu);
    });
    int cancelled = 0;
    int ok = 0;
    auto callback = [&](const ModbusResult& r) {
        (r.error == ModbusError::Cancelled ? cancelled : ok)++;
    };
    f.client->submit(ModbusRequest::readHolding(1, 1, 1), nullptr, callback);
    ASSERT_TRUE(waitUntil([&] { return gate->entered == 1; }));
    for (quint16 a = 2; a < 6; ++a)
        f.client->submit(ModbusRequest::readHolding(1, a, 1), nullptr, callback);
    f.client->cancelAll();
    gate->release();
    ASSERT_TRUE(waitUntil([&] { return cancelled + ok == 5; }));
    EXPECT_EQ(cancelled, 4);
    EXPECT_EQ(ok, 1);
    EXPECT_EQ(f.mock->requestCount(), 1);
}

TEST(ModbusClientTest, RetriesTimeoutsAndGarbledRepliesButNotExceptions)
{
    ConnectionSettings settings;
    settings.retries = 2;
    QByteArray (*silent)(const QByteArray&) = [](const QByteArray&) { return QByteArray(); };
    {
        MockClient f(silent, settings);
        const ModbusResult r = f.client->execute(ModbusRequest::readHolding(1, 0, 1));
        EXPECT_EQ(r.error, ModbusError::Timeout);
        EXPECT_EQ(r.attempts, 3);
        EXPECT_EQ(f.mock->requestCount(), 3);
        ModbusRequest once = ModbusRequest::readHolding(1, 0, 1);
        once.retries = 0; // per request, overriding the connection's 2
        EXPECT_EQ(f.client->execute(once).attempts, 1);
        EXPECT_EQ(f.mock->requestCount(), 4);
    }
    {
        MockClient f(
            [](const QByteArray& adu) {
                QByteArray reply = echoDevice(adu);
                reply[reply.size() - 1] = char(reply.at(reply.size() - 1) ^ 0x55);
                return reply;
            },
            settings);
        const ModbusResult r = f.client->execute(ModbusRequest::readHolding(1, 0, 1));
        EXPECT_EQ(r.error, ModbusError::CrcError);
        EXPECT_EQ(r.attempts, 3);
    }
    {
        MockClient f(
            [](const QByteArray& adu) { return RtuFrame::encodeException(quint8(adu[0]), 3, 2); },
            settings);
        const ModbusResult r = f.client->execute(ModbusRequest::readHolding(1, 0, 1));
        EXPECT_EQ(r.error, ModbusError::Exception);
        EXPECT_EQ(r.attempts, 1);
        EXPECT_EQ(f.mock->requestCount(), 1);
    }
    {
        MockClient f([](const QByteArray&) { return RtuFrame::encodeReadReply(9, 3, {1}); },
                     settings);
        // A foreign reply is garbled for this request: asked again (issue 11).
        const ModbusResult r = f.client->execute(ModbusRequest::readHolding(1, 0, 1));
        EXPECT_EQ(r.error, ModbusError::WrongSlave);
        EXPECT_EQ(r.attempts, 3);
        EXPECT_EQ(f.mock->requestCount(), 3);
    }
    {
        // A reply that does not match the request (byte count for another quantity, a write
        // echo with another value) is retried, and the retry's good answer is taken.
        auto calls = std::make_shared<std::atomic<int>>(0);
        MockClient f(
            [calls](const QByteArray& adu) {
                ModbusRequest request;
                RtuFrame::decodeRequest(adu, &request);
                if (++*calls % 2 == 1)
                    return request.isRead()
                               ? RtuFrame::encodeReadReply(1, 3, {1, 2})
                               : RtuFrame::encodeWriteSingleReply(1, request.address, 999);
                return echoDevice(adu);
            },
            settings);
        ModbusResult r = f.client->execute(ModbusRequest::readHolding(1, 7, 1));
        EXPECT_EQ(r.error, ModbusError::Ok);
        EXPECT_EQ(r.attempts, 2);
        EXPECT_EQ(r.registers, QVector<quint16>({7}));
        r = f.client->execute(ModbusRequest::writeSingle(1, 0x10, 5));
        EXPECT_EQ(r.error, ModbusError::Ok);
        EXPECT_EQ(r.attempts, 2);
        EXPECT_EQ(r.registers, QVector<quint16>({5}));
    }
    {
        auto calls = std::make_shared<std::atomic<int>>(0);
        MockClient f(
            [calls](const QByteArray& adu) {
                return ++*calls == 1 ? QByteArray() : echoDevice(adu);
            },
            settings);
        const ModbusResult r = f.client->execute(ModbusRequest::readHolding(1, 7, 1));
        EXPECT_EQ(r.error, ModbusError::Ok);
        EXPECT_EQ(r.attempts, 2);
        EXPECT_EQ(r.registers, QVector<quint16>({7}));
    }
}

TEST(ModbusClientTest, RetriesBusyExceptionsWhereNothingWasExecuted)
{
    // Found by the fault matrix (issue 11): a drive busy with internal processing answers
    // exception 06 (Modbus: busy), a DBU answers 04 (its manual: "internal processing, BUSY
    // is ON"). Nothing was executed: a read is asked again, a write only after 06; a busy
    // 1 % of the time must not end a 32-drive backup.
    ConnectionSettings settings;
    settings.retries = 2;
    for (const quint8 code : {quint8(0x04), quint8(0x06)}) {
        auto calls = std::make_shared<std::atomic<int>>(0);
        MockClient f(
            [calls, code](const QByteArray& adu) {
                return ++*calls == 1
                           ? RtuFrame::encodeException(quint8(adu[0]), quint8(adu[1]), code)
                           : echoDevice(adu);
            },
            settings);
        const ModbusResult r = f.client->execute(ModbusRequest::readHolding(1, 7, 1));
        EXPECT_EQ(r.error, ModbusError::Ok) << int(code);
        EXPECT_EQ(r.attempts, 2) << int(code);
        EXPECT_EQ(r.registers, QVector<quint16>({7})) << int(code);
    }
    {
        auto calls = std::make_shared<std::atomic<int>>(0);
        MockClient f(
            [calls](const QByteArray& adu) {
                return ++*calls == 1 ? RtuFrame::encodeException(quint8(adu[0]), 6, 0x06)
                                     : echoDevice(adu);
            },
            settings);
        const ModbusResult r = f.client->execute(ModbusRequest::writeSingle(1, 0x10, 5));
        EXPECT_EQ(r.error, ModbusError::Ok);
        EXPECT_EQ(r.attempts, 2);
    }
    {
        // A write refused with 04 may be a refusal (a value out of range, a command that
        // cannot run now): not repeated here.
        MockClient f(
            [](const QByteArray& adu) {
                return RtuFrame::encodeException(quint8(adu[0]), 6, 0x04);
            },
            settings);
        const ModbusResult r = f.client->execute(ModbusRequest::writeSingle(1, 0x10, 5));
        EXPECT_EQ(r.error, ModbusError::Exception);
        EXPECT_EQ(r.attempts, 1);
        EXPECT_EQ(f.mock->requestCount(), 1);
    }
}

TEST(ModbusClientTest, BroadcastNeitherWaitsNorRetries)
{
    ConnectionSettings settings;
    settings.retries = 3;
    settings.timeoutMs = 5000;
    MockClient f([](const QByteArray&) { return QByteArray(); }, settings);
    f.mock->setNoReplyDelayMs(5000);
    QElapsedTimer timer;
    timer.start();
    const ModbusResult r = f.client->execute(ModbusRequest::writeSingle(0, 0x2000, 1));
    EXPECT_EQ(r.error, ModbusError::Ok);
    EXPECT_EQ(r.attempts, 1);
    EXPECT_LT(timer.elapsed(), 500);
    EXPECT_EQ(f.mock->requestCount(), 1);
}

TEST(ModbusClientTest, InvalidRequestSendsNothing)
{
    MockClient f(echoDevice);
    ModbusResult viaCallback;
    bool called = false;
    f.client->submit(ModbusRequest::readHolding(1, 0, 0), nullptr, [&](const ModbusResult& r) {
        viaCallback = r;
        called = true;
    });
    EXPECT_FALSE(called); // never synchronously inside submit()
    ASSERT_TRUE(waitUntil([&] { return called; }));
    EXPECT_EQ(viaCallback.error, ModbusError::InvalidRequest);
    EXPECT_FALSE(viaCallback.message.isEmpty());
    EXPECT_EQ(f.client->execute(ModbusRequest::readHolding(0, 0, 1)).error,
              ModbusError::InvalidRequest);
    EXPECT_EQ(f.mock->requestCount(), 0);
}

TEST(ModbusClientTest, CallbacksRunOnTheContextThread)
{
    MockClient f(echoDevice);
    QThread other;
    other.start();
    QObject onOther;
    onOther.moveToThread(&other);
    std::atomic<QThread*> seenOther{nullptr};
    QThread* seenClient = nullptr;
    quint64 finishedId = 0;
    QObject::connect(f.client.get(), &ModbusClient::finished,
                     [&finishedId](quint64 id, const ModbusResult&) { finishedId = id; });
    f.client->submit(ModbusRequest::readHolding(1, 1, 1), &onOther,
                     [&](const ModbusResult&) { seenOther = QThread::currentThread(); });
    const auto id =
        f.client->submit(ModbusRequest::readHolding(1, 2, 1), nullptr,
                         [&](const ModbusResult&) { seenClient = QThread::currentThread(); });
    ASSERT_TRUE(waitUntil([&] { return seenOther.load() && seenClient && finishedId == id; }));
    EXPECT_EQ(seenOther.load(), &other);
    EXPECT_EQ(seenClient, QThread::currentThread());
    other.quit();
    other.wait();
}

TEST(ModbusClientTest, ExecuteFromAnotherThread)
{
    MockClient f(echoDevice);
    ModbusResult r;
    std::thread caller([&] { r = f.client->execute(ModbusRequest::writeSingle(1, 5, 77)); });
    caller.join();
    EXPECT_EQ(r.error, ModbusError::Ok);
    EXPECT_EQ(r.registers, QVector<quint16>({77}));
}

TEST(ModbusClientTest, AContextDeletedBeforeItsResultHearsNothing)
{
    MockClient f(echoDevice);
    auto context = std::make_unique<QObject>();
    bool calledDeleted = false;
    bool calledKept = false;
    quint64 lastFinished = 0;
    QObject::connect(f.client.get(), &ModbusClient::finished,
                     [&lastFinished](quint64 id, const ModbusResult&) { lastFinished = id; });
    f.client->submit(ModbusRequest::readHolding(1, 1, 1), context.get(),
                     [&](const ModbusResult&) { calledDeleted = true; });
    const auto kept = f.client->submit(ModbusRequest::readHolding(1, 2, 1), nullptr,
                                       [&](const ModbusResult&) { calledKept = true; });
    context.reset();
    ASSERT_TRUE(waitUntil([&] { return calledKept && lastFinished == kept; }));
    EXPECT_FALSE(calledDeleted);
}

// A failure handler that disconnects deletes the client from inside its own callback.
TEST(ModbusClientTest, ACallbackMayDeleteTheClient)
{
    MockClient f(echoDevice);
    bool finishedAfter = false;
    bool called = false;
    QObject::connect(f.client.get(), &ModbusClient::finished,
                     [&finishedAfter](quint64, const ModbusResult&) { finishedAfter = true; });
    f.client->submit(ModbusRequest::readHolding(1, 1, 1), nullptr, [&](const ModbusResult&) {
        called = true;
        f.client.reset();
    });
    f.client->submit(ModbusRequest::readHolding(1, 2, 1), nullptr, [&](const ModbusResult&) {
        ADD_FAILURE() << "a deleted client delivered a result";
    });
    ASSERT_TRUE(waitUntil([&] { return called; }));
    QCoreApplication::processEvents();
    EXPECT_FALSE(f.client);
    EXPECT_FALSE(finishedAfter);
}
