#pragma once

#include "transport/ConnectionSettings.h"
#include "transport/ModbusClient.h"
#include "transport/ModbusRequest.h"
#include "transport/ModbusResult.h"

#include <future>
#include <memory>
#include <thread>

namespace opentop {

class ModbusBackend;

// The thread behind ModbusClient. It owns the backend: open, every transact and close run on
// it, so a libmodbus context never changes threads. Requests wait in one queue per priority
// (User > Normal > Poll), FIFO within each. Results go back as queued calls to each request's
// client, which passes them on to who asked (ModbusClient::deliver).
class ModbusClientWorker
{
public:
    using Promise = std::shared_ptr<std::promise<ModbusResult>>;

    ModbusClientWorker(ModbusClient* client, std::unique_ptr<ModbusBackend> backend,
                       const ConnectionSettings& settings);
    // Stops the thread: queued requests are dropped, a request on the wire is interrupted.
    // Returns within about 1.5 s; a backend stuck in a call that cannot be interrupted is left
    // to finish (and close its port) on its own thread.
    ~ModbusClientWorker();

    void open(std::shared_ptr<std::promise<QString>> done = {});
    void close();
    bool isOpen() const;
    QString describe() const;
    // The backend's line report as of the last successful open; any thread.
    SerialLineReport lineReport() const;

    // Returns the request's id. Its result goes to `promise` (on this thread) and to
    // ModbusClient::deliver (on the client's).
    quint64 submit(const ModbusRequest& request, Promise promise = {});
    bool cancel(quint64 id);
    // The per-drive format table (ConnectionSettings::driveLines); an unset format, or the
    // port's, removes the drive's entry. Any thread; used from the next transaction on.
    void setDriveLine(int slave, const LineFormat& format);
    void cancelAll();
    int pendingCount() const;
    // While held, the Poll queue is not served (ModbusClient::holdPolling).
    void setPollingHeld(bool held);

    static constexpr int kStopWaitMs = 1500;

private:
    struct State;
    struct Item;
    static void run(std::shared_ptr<State> state);
    static ModbusResult execute(State& state, const Item& item);
    static ModbusResult executeOne(State& state, const Item& item);
    static void deliver(State& state, const Item& item, ModbusResult result);

    std::shared_ptr<State> m_state;
    std::thread m_thread;
    std::future<void> m_exited;
};

} // namespace opentop
