#include "transport/ModbusClient.h"

#include "transport/ModbusBackend.h"
#include "transport/ModbusClientWorker.h"

namespace opentop {

ModbusClient::ModbusClient(std::unique_ptr<ModbusBackend> backend,
                           const ConnectionSettings& settings, QObject* parent)
    : QObject(parent)
    , m_settings(settings)
{
    qRegisterMetaType<opentop::ModbusResult>("opentop::ModbusResult");
    m_worker = std::make_unique<ModbusClientWorker>(this, std::move(backend), settings);
}

ModbusClient::~ModbusClient()
{
    m_worker.reset(); // bounded: see ModbusClientWorker::~ModbusClientWorker
}

QString ModbusClient::describe() const
{
    return m_worker->describe();
}

void ModbusClient::open()
{
    m_worker->open();
}

QString ModbusClient::openBlocking()
{
    auto done = std::make_shared<std::promise<QString>>();
    std::future<QString> error = done->get_future();
    m_worker->open(done);
    return error.get();
}

void ModbusClient::close()
{
    m_worker->close();
}

bool ModbusClient::isOpen() const
{
    return m_worker->isOpen();
}

SerialLineReport ModbusClient::lineReport() const
{
    return m_worker->lineReport();
}

int ModbusClient::adapterLatencyMs() const
{
    return m_worker->lineReport().adapterLatencyMs();
}

void ModbusClient::setDriveLine(int slave, const LineFormat& format)
{
    const bool own = format.isSet() && format != m_settings.line();
    if (own ? m_settings.driveLines.value(slave) == format : !hasOwnLine(slave))
        return;
    if (own)
        m_settings.driveLines.insert(slave, format);
    else
        m_settings.driveLines.remove(slave);
    m_worker->setDriveLine(slave, format);
    emit driveLineChanged(slave);
}

LineFormat ModbusClient::driveLine(int slave) const
{
    return m_settings.driveLines.value(slave, m_settings.line());
}

ModbusClient::RequestId ModbusClient::submit(const ModbusRequest& request, QObject* context,
                                             Callback callback)
{
    // Held across the worker's submit, so a result can never be delivered before it is known
    // who should hear of it.
    std::lock_guard<std::mutex> lock(m_pendingMutex);
    const RequestId id = m_worker->submit(request);
    if (callback)
        m_pending.emplace(id, Pending{context, context != nullptr, std::move(callback)});
    return id;
}

void ModbusClient::deliver(quint64 id, const ModbusResult& result)
{
    Pending pending;
    {
        std::lock_guard<std::mutex> lock(m_pendingMutex);
        auto it = m_pending.find(id);
        if (it != m_pending.end()) {
            pending = std::move(it->second);
            m_pending.erase(it);
        }
    }
    if (pending.callback) {
        QObject* target = pending.hasContext ? pending.context.data() : this;
        if (target && target->thread() == thread()) {
            // The callback may delete this client (a disconnect on a failure).
            QPointer<ModbusClient> self(this);
            pending.callback(result);
            if (!self)
                return;
        } else if (target) {
            auto callback = std::move(pending.callback);
            QMetaObject::invokeMethod(
                target, [callback, result] { callback(result); }, Qt::QueuedConnection);
        }
    }
    emit finished(id, result);
}

ModbusResult ModbusClient::execute(const ModbusRequest& request)
{
    // The worker fulfils the promise itself, so this needs no event loop on this thread.
    auto done = std::make_shared<std::promise<ModbusResult>>();
    std::future<ModbusResult> result = done->get_future();
    m_worker->submit(request, done);
    return result.get();
}

bool ModbusClient::cancel(RequestId id)
{
    return m_worker->cancel(id);
}

void ModbusClient::cancelAll()
{
    m_worker->cancelAll();
}

int ModbusClient::pendingCount() const
{
    return m_worker->pendingCount();
}

void ModbusClient::holdPolling()
{
    if (m_pollHolds++ > 0)
        return;
    m_worker->setPollingHeld(true);
    emit pollingHeldChanged(true);
}

void ModbusClient::releasePolling()
{
    if (m_pollHolds == 0 || --m_pollHolds > 0)
        return;
    m_worker->setPollingHeld(false);
    emit pollingHeldChanged(false);
}

} // namespace opentop
