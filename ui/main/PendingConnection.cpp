#include "ui/main/PendingConnection.h"

#include "transport/ModbusClient.h"

namespace opentop {

PendingConnection::PendingConnection(Adopt adopt, Refuse refuse)
    : m_adopt(std::move(adopt))
    , m_refuse(std::move(refuse))
{
}

PendingConnection::~PendingConnection() = default;

bool PendingConnection::canWait(const ConnectionSettings& working, const ConnectionSettings& next)
{
    return !(next.kind == ConnectionSettings::Kind::Serial &&
             working.kind == ConnectionSettings::Kind::Serial && next.port == working.port);
}

void PendingConnection::open(std::unique_ptr<ModbusClient> client,
                             const ConnectionSettings& settings,
                             const QHash<int, QString>& knownTypes)
{
    m_client = std::move(client);
    m_settings = settings;
    m_types = knownTypes;
    connect(m_client.get(), &ModbusClient::opened, this, [this](bool ok, const QString& why) {
        if (!ok) {
            const ConnectionSettings failed = m_settings;
            drop();
            m_refuse(failed, why);
            return;
        }
        std::unique_ptr<ModbusClient> opened = std::move(m_client);
        disconnect(opened.get(), &ModbusClient::opened, this, nullptr);
        m_adopt(std::move(opened), m_settings, m_types);
    });
    m_client->open();
}

void PendingConnection::drop()
{
    if (!m_client)
        return;
    disconnect(m_client.get(), nullptr, this, nullptr);
    // Possibly inside its own signal: deleted once that has returned.
    m_client.release()->deleteLater();
}

} // namespace opentop
