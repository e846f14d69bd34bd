#include "ModbusClient.h"

#include "ModbusBackend.h"
#include "ModbusClientWorker.h"

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

ModbusClient::RequestId ModbusClient::submit(const ModbusRequest& request, QObject* context,
                                             Callback callback)
{
    return m_worker->submit(request, context, std::move(callback));
}

ModbusResult ModbusClient::execute(const ModbusRequest& request)
{
    // The worker fulfils the promise itself, so this needs no event loop on this thread.
    auto done = std::make_shared<std::promise<ModbusResult>>();
    std::future<ModbusResult> result = done->get_future();
    m_worker->submit(request, nullptr, {}, done);
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

} // namespace opentop
