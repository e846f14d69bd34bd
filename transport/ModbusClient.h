#pragma once

#include "transport/ConnectionSettings.h"
#include "transport/ModbusRequest.h"
#include "transport/ModbusResult.h"
#include "transport/SerialLineReport.h"

#include <QObject>
#include <QPointer>
#include <functional>
#include <memory>
#include <mutex>
#include <unordered_map>

namespace opentop {

class ModbusBackend;
class TrafficLog;
class ModbusClientWorker;

// The bus as the rest of the program sees it. A worker thread owns the backend (and so the
// libmodbus context); callers queue requests and get results asynchronously. User requests
// overtake queued polling. Destruction stops the worker within a bounded time.
class ModbusClient : public QObject
{
    Q_OBJECT
public:
    using RequestId = quint64;
    using Callback = std::function<void(const ModbusResult&)>;

    ModbusClient(std::unique_ptr<ModbusBackend> backend, const ConnectionSettings& settings,
                 QObject* parent = nullptr);
    ~ModbusClient() override;

    const ConnectionSettings& settings() const { return m_settings; }
    QString describe() const;

    // Opens the connection on the worker; the result arrives as opened().
    void open();
    // Blocking open for non-GUI threads; returns an error text, empty on success.
    QString openBlocking();
    void close();
    bool isOpen() const;
    // What the serial driver accepted at the last successful open (RS-485 direction, low
    // latency), read back; empty before that and for TCP or simulated buses. Any thread.
    SerialLineReport lineReport() const;
    // How long the adapter may hold a reply's bytes before passing them on, in ms, to add to
    // per-request waits (a scan's wait per machine number): 0 when there is nothing to allow
    // for (not open yet, not a serial line, not a UART, low latency on); the adapter's latency
    // timer when sysfs has one above 1 ms; 16 ms for a USB adapter that refused low latency.
    // Same rules as SerialLineReport::adapterLatencyMs(). Any thread.
    int adapterLatencyMs() const;

    // Drives that talk another format than the port's (ConnectionSettings::driveLines):
    // requests to them carry it from the next transaction on; an unset format, or the port's,
    // removes the entry. Client thread.
    void setDriveLine(int slave, const LineFormat& format);
    // The drive's format: its entry, else the port's.
    LineFormat driveLine(int slave) const;
    bool hasOwnLine(int slave) const { return m_settings.driveLines.contains(slave); }

    // Queues a request. `callback` runs on `context`'s thread (this client's when null);
    // finished() is emitted as well. Invalid requests are answered with InvalidRequest, never
    // synchronously. A context deleted before its result arrives gets no callback; delete it
    // on its own thread. Nothing is delivered once the client is destroyed.
    RequestId submit(const ModbusRequest& request, QObject* context = nullptr,
                     Callback callback = {});
    // Blocking convenience for the command line and tests. Never call it on the GUI thread.
    ModbusResult execute(const ModbusRequest& request);
    // Removes a request that has not been sent yet; true when it was still queued. A request on
    // the wire completes (a half-sent frame would leave the bus in an unknown state).
    bool cancel(RequestId id);
    void cancelAll();
    int pendingCount() const;

    // A bus scan owns the line: while a hold is in place, requests of Poll priority stay
    // queued, in order, and go out once the last hold is released; Normal and User requests
    // (a write, STOP ALL) still go. Counted, so that holds may nest. Call on this client's
    // thread; pollingHeldChanged() follows at once.
    void holdPolling();
    void releasePolling();
    bool isPollingHeld() const { return m_pollHolds > 0; }

signals:
    void opened(bool ok, const QString& error);
    void closed();
    void finished(quint64 id, const opentop::ModbusResult& result);
    // The port failed while in use (e.g. USB adapter unplugged): a PortError after which the
    // backend closed itself. Emitted once per open(); later requests get NotConnected.
    void connectionLost(const QString& error);
    // Polling waits (a scan holds the bus) or goes on again.
    void pollingHeldChanged(bool held);
    // A drive's line format was set or removed (setDriveLine).
    void driveLineChanged(int slave);

private:
    friend class ModbusClientWorker;

    // Who hears of a result. Kept on this side: a QPointer must not be copied or destroyed on
    // the worker thread while its object is being deleted on another.
    struct Pending
    {
        QPointer<QObject> context;
        bool hasContext = false;
        Callback callback;
    };

    // Runs on this client's thread, posted by the worker.
    void deliver(quint64 id, const ModbusResult& result);

    ConnectionSettings m_settings;
    std::mutex m_pendingMutex; // submit() may be called from a thread other than this client's
    std::unordered_map<quint64, Pending> m_pending;
    std::unique_ptr<ModbusClientWorker> m_worker;
    int m_pollHolds = 0;
};

} // namespace opentop

Q_DECLARE_METATYPE(opentop::ModbusResult)
