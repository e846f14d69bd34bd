#include "transport/ModbusClientWorker.h"

#include "transport/DriveLineTable.h"
#include "transport/ModbusBackend.h"
#include "transport/RetryPolicy.h"
#include "transport/TransportLog.h"

#include <QCoreApplication>
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#ifdef Q_OS_WIN
#include <windows.h>

#include <mmsystem.h>
#else
#include <sys/prctl.h>
#endif

namespace opentop {

struct ModbusClientWorker::Item
{
    quint64 id = 0;
    ModbusRequest request;
    Promise promise; // a blocking caller on another thread
};

struct ModbusClientWorker::State
{
    struct Control
    {
        bool open = true; // false: close
        std::shared_ptr<std::promise<QString>> done;
    };

    std::mutex mutex; // guards the queues, controls, inFlight, stop and backend's lifetime
    std::condition_variable wake;
    std::deque<Item> queues[3]; // indexed by ModbusRequest::Priority
    std::deque<Control> controls;
    quint64 inFlight = 0;
    bool stop = false;
    bool pollingHeld = false; // a scan owns the bus: the Poll queue waits

    // The queue served next (-1: none): the highest priority's, Poll's not while held.
    int next() const
    {
        for (int q = 2; q >= 0; --q)
            if (!queues[q].empty() && !(q == 0 && pollingHeld))
                return q;
        return -1;
    }

    std::atomic<bool> interrupt{false};
    std::atomic<bool> open{false};
    std::atomic<quint64> nextId{1};
    bool lostReported = false; // worker thread only
    RetryPolicy retryPolicy;   // worker thread only

    std::unique_ptr<ModbusBackend> backend;
    ConnectionSettings settings;
    DriveLineTable driveLines;
    QString description;
    mutable std::mutex reportMutex;
    SerialLineReport lineReport; // copied from the backend after each open

    std::mutex deliveryMutex; // held while posting to the client, so it can be cut off
    ModbusClient* client = nullptr;
    std::promise<void> exited;

    // Runs `f(client)` on the client's thread, unless the client is gone.
    template <typename F> void postToClient(F f)
    {
        std::lock_guard<std::mutex> lock(deliveryMutex);
        if (!client)
            return;
        ModbusClient* target = client;
        QMetaObject::invokeMethod(
            target, [target, f] { f(target); }, Qt::QueuedConnection);
    }
};

namespace {

ModbusResult makeResult(ModbusError error, const QString& message)
{
    ModbusResult result;
    result.error = error;
    result.message = message;
    return result;
}

} // namespace

ModbusClientWorker::ModbusClientWorker(ModbusClient* client, std::unique_ptr<ModbusBackend> backend,
                                       const ConnectionSettings& settings)
    : m_state(std::make_shared<State>())
{
    Q_ASSERT(backend);
    m_state->client = client;
    m_state->settings = settings;
    m_state->driveLines.reset(settings.line(), settings.driveLines);
    m_state->description = backend->describe();
    backend->setInterruptFlag(&m_state->interrupt);
    m_state->backend = std::move(backend);
    m_exited = m_state->exited.get_future();
    m_thread = std::thread(&ModbusClientWorker::run, m_state);
}

ModbusClientWorker::~ModbusClientWorker()
{
    {
        std::lock_guard<std::mutex> lock(m_state->deliveryMutex);
        m_state->client = nullptr;
    }
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        m_state->stop = true;
    }
    m_state->interrupt = true;
    m_state->wake.notify_all();
    if (m_exited.wait_for(std::chrono::milliseconds(kStopWaitMs)) == std::future_status::ready) {
        m_thread.join();
        return;
    }
    // The backend is stuck in a call that ignores the interrupt (e.g. a TCP connect). Let it
    // finish on its own thread, which then closes the port; it must not log to a TrafficLog
    // that may be gone by then.
    qCWarning(lcTransport) << "bus worker did not stop in time; detaching" << m_state->description;
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        if (m_state->backend)
            m_state->backend->setTrafficLog(nullptr);
    }
    m_thread.detach();
}

void ModbusClientWorker::open(std::shared_ptr<std::promise<QString>> done)
{
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        m_state->controls.push_back({true, std::move(done)});
    }
    m_state->wake.notify_all();
}

void ModbusClientWorker::close()
{
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        m_state->controls.push_back({false, {}});
    }
    m_state->wake.notify_all();
}

bool ModbusClientWorker::isOpen() const
{
    return m_state->open;
}

SerialLineReport ModbusClientWorker::lineReport() const
{
    std::lock_guard<std::mutex> lock(m_state->reportMutex);
    return m_state->lineReport;
}

QString ModbusClientWorker::describe() const
{
    return m_state->description;
}

quint64 ModbusClientWorker::submit(const ModbusRequest& request, Promise promise)
{
    Item item;
    item.id = m_state->nextId++;
    item.request = request;
    item.promise = std::move(promise);

    const QString invalid = request.validate();
    if (!invalid.isEmpty()) {
        deliver(*m_state, item, makeResult(ModbusError::InvalidRequest, invalid));
        return item.id;
    }
    const quint64 id = item.id;
    const int queue = std::clamp(int(request.priority), 0, 2);
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        m_state->queues[queue].push_back(std::move(item));
    }
    m_state->wake.notify_all();
    return id;
}

bool ModbusClientWorker::cancel(quint64 id)
{
    Item found;
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        bool removed = false;
        for (auto& queue : m_state->queues) {
            for (auto it = queue.begin(); it != queue.end(); ++it) {
                if (it->id == id) {
                    found = std::move(*it);
                    queue.erase(it);
                    removed = true;
                    break;
                }
            }
            if (removed)
                break;
        }
        if (!removed)
            return false;
    }
    deliver(
        *m_state, found,
        makeResult(ModbusError::Cancelled,
                   QCoreApplication::translate("opentop::Transport", "cancelled before sending")));
    return true;
}

void ModbusClientWorker::cancelAll()
{
    std::deque<Item> dropped;
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        for (int q = 2; q >= 0; --q) {
            for (auto& item : m_state->queues[q])
                dropped.push_back(std::move(item));
            m_state->queues[q].clear();
        }
    }
    for (const Item& item : dropped)
        deliver(*m_state, item,
                makeResult(
                    ModbusError::Cancelled,
                    QCoreApplication::translate("opentop::Transport", "cancelled before sending")));
}

void ModbusClientWorker::setPollingHeld(bool held)
{
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        m_state->pollingHeld = held;
    }
    m_state->wake.notify_all();
}

int ModbusClientWorker::pendingCount() const
{
    std::lock_guard<std::mutex> lock(m_state->mutex);
    int count = m_state->inFlight ? 1 : 0;
    for (const auto& queue : m_state->queues)
        count += int(queue.size());
    return count;
}

void ModbusClientWorker::run(std::shared_ptr<State> state)
{
#ifdef Q_OS_WIN
    // Windows' timer ticks every 15.6 ms by default: the line's gaps, sleeps and 1 ms polls
    // (LineInput_win.cpp) need its finest, 1 ms, while the bus is in use.
    timeBeginPeriod(1);
#else
    // Linux lets a thread's timed waits end up to 50 µs late by default; the line's gaps and
    // waits are a few hundred µs long at 115200 bit/s, so this thread asks for 1 µs.
    ::prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
#endif
    State& s = *state;
    for (;;) {
        std::unique_lock<std::mutex> lock(s.mutex);
        s.wake.wait(lock, [&s] { return s.stop || !s.controls.empty() || s.next() >= 0; });
        if (s.stop)
            break;
        if (!s.controls.empty()) {
            State::Control control = s.controls.front();
            s.controls.pop_front();
            lock.unlock();
            if (control.open) {
                QString error;
                const bool ok = s.backend->isOpen() || s.backend->open(&error);
                if (!ok && error.isEmpty())
                    error = QCoreApplication::translate("opentop::Transport", "cannot open %1")
                                .arg(s.description);
                if (ok) {
                    std::lock_guard<std::mutex> reportLock(s.reportMutex);
                    s.lineReport = s.backend->lineReport();
                }
                s.open = ok;
                s.lostReported = false;
                if (control.done)
                    control.done->set_value(ok ? QString() : error);
                s.postToClient([ok, error](ModbusClient* c) { emit c->opened(ok, error); });
            } else {
                s.backend->close();
                s.open = false;
                s.postToClient([](ModbusClient* c) { emit c->closed(); });
            }
            continue;
        }
        const int q = s.next();
        Item item = std::move(s.queues[q].front());
        s.queues[q].pop_front();
        s.inFlight = item.id;
        lock.unlock();
        ModbusResult result = execute(s, item);
        lock.lock();
        s.inFlight = 0;
        lock.unlock();
        deliver(s, item, std::move(result));
    }

    // Stopping: what is still queued is never sent. Only blocked execute() callers hear of it.
    std::deque<Item> dropped;
    std::deque<State::Control> controls;
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        for (auto& queue : s.queues) {
            for (auto& item : queue)
                dropped.push_back(std::move(item));
            queue.clear();
        }
        controls.swap(s.controls);
    }
    const QString closing = QCoreApplication::translate("opentop::Transport", "client closed");
    for (const Item& item : dropped)
        deliver(s, item, makeResult(ModbusError::Cancelled, closing));
    for (const auto& control : controls)
        if (control.done)
            control.done->set_value(closing);
    // The libmodbus context is freed here, on the thread that used it.
    std::unique_ptr<ModbusBackend> backend;
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        backend = std::move(s.backend);
    }
    backend->close();
    backend.reset();
    s.open = false;
#ifdef Q_OS_WIN
    timeEndPeriod(1);
#endif
    s.exited.set_value();
}

void ModbusClientWorker::setDriveLine(int slave, const LineFormat& format)
{
    m_state->driveLines.set(slave, format);
}

ModbusResult ModbusClientWorker::execute(State& s, const Item& item)
{
    const QVector<LineFormat> formats = s.driveLines.formatsFor(item.request);
    ModbusResult result;
    for (const LineFormat& format : formats) {
        Item one = item;
        one.request.line = format;
        result = executeOne(s, one);
        if (!result.ok())
            break;
    }
    return result;
}

ModbusResult ModbusClientWorker::executeOne(State& s, const Item& item)
{
    const ModbusRequest& request = item.request;
    if (!s.backend->isOpen())
        return makeResult(
            ModbusError::NotConnected,
            QCoreApplication::translate("opentop::Transport", "%1 is not open").arg(s.description));
    const int timeoutMs = request.timeoutMs >= 0 ? request.timeoutMs : s.settings.timeoutMs;
    // A broadcast is never repeated: every device would execute it again.
    const int retries =
        request.isBroadcast() ? 0 : s.retryPolicy.retriesFor(request.retries, s.settings.retries);
    ModbusResult result;
    int lateFrom = -1; // a reply to an earlier request seen by any attempt (see below)
    bool garbled = false;
    for (int attempt = 1;; ++attempt) {
        result = s.backend->transact(request, timeoutMs);
        result.attempts = attempt;
        garbled |= result.discardedGarbled;
        // The frame taken in place of the answer names its sender; the drain after it may
        // also have swallowed this request's own answer, which is no news.
        if (result.error == ModbusError::WrongSlave && !result.reply.isEmpty())
            lateFrom = quint8(result.reply.at(0));
        else if (result.lateReplyFrom >= 0 && result.lateReplyFrom != request.slave)
            lateFrom = result.lateReplyFrom;
        if (result.error == ModbusError::PortError && !s.backend->isOpen()) {
            s.open = false;
            if (!s.lostReported) {
                s.lostReported = true;
                const QString message = result.message;
                s.postToClient([message](ModbusClient* c) { emit c->connectionLost(message); });
            }
        }
        // No valid answer to this request: the backend has resynchronised (the line has
        // fallen silent, what came was discarded), so asking again is safe. A reply from
        // another machine number or one that does not match the request (byte count, echo) is
        // as garbled as a bad CRC. An exception is a valid answer and is not repeated, except
        // "busy": 06 (nothing executed) for any request, and 04 for a read, which a DBU gives
        // while busy with internal processing and which has no effect to repeat.
        const bool busy =
            result.error == ModbusError::Exception &&
            (result.exceptionCode == 0x06 || (result.exceptionCode == 0x04 && request.isRead()));
        const bool retryable = result.error == ModbusError::Timeout ||
                               result.error == ModbusError::CrcError ||
                               result.error == ModbusError::WrongSlave ||
                               result.error == ModbusError::MalformedReply || busy;
        if (!retryable || attempt > retries || s.interrupt)
            break;
        qCDebug(lcTransport) << "retrying" << request.describe() << "after" << result.errorText();
    }
    if (!request.isBroadcast())
        s.retryPolicy.record(result);
    // A retry that succeeded must not hide that another drive's late reply came meanwhile: a
    // scan still running asks that drive again (BusScanner listens to every result).
    if (result.lateReplyFrom < 0 && lateFrom != request.slave)
        result.lateReplyFrom = lateFrom;
    result.discardedGarbled = garbled;
    return result;
}

void ModbusClientWorker::deliver(State& s, const Item& item, ModbusResult result)
{
    if (item.promise)
        item.promise->set_value(result);
    std::lock_guard<std::mutex> lock(s.deliveryMutex);
    if (!s.client)
        return;
    ModbusClient* client = s.client;
    const quint64 id = item.id;
    // Moved: this thread keeps no share of the result's data once it is posted.
    QMetaObject::invokeMethod(
        client, [client, id, result = std::move(result)] { client->deliver(id, result); },
        Qt::QueuedConnection);
}

} // namespace opentop
