#include "tests/soak/ModelSoak.h"

#include "connection/BackendFactory.h"
#include "model/bus/BusDrives.h"
#include "model/bus/BusScanner.h"
#include "model/monitor/MonitorHub.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ConnectionSettings.h"
#include "transport/ModbusClient.h"

#include <QDateTime>

namespace opentop::soak {

ModelSoak::ModelSoak(int baud, int pollMs, QObject* parent)
    : SoakPart(parent)
    , m_baud(baud)
    , m_pollMs(pollMs)
{
}

ModelSoak::~ModelSoak()
{
    stop();
}

bool ModelSoak::start(const QString& pty, QString* error)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Serial;
    settings.port = pty;
    settings.baud = m_baud;
    BackendFactory::Made made = BackendFactory::makeClient(settings);
    if (!made.client) {
        *error = made.error;
        return false;
    }
    m_client = std::move(made.client);
    const QString openError = m_client->openBlocking();
    if (!openError.isEmpty()) {
        *error = openError;
        return false;
    }
    connect(m_client.get(), &ModbusClient::connectionLost, this,
            [this](const QString& why) { emit failed(QStringLiteral("model: ") + why); });
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    m_drives = std::make_unique<BusDrives>(m_client.get(), registry);
    m_hub = std::make_unique<MonitorHub>(m_drives.get());
    m_hub->setInterval(m_pollMs);
    connect(m_hub.get(), &MonitorHub::sample, this, [this] { ++m_samples; });
    connect(m_hub.get(), &MonitorHub::error, this, [this] { ++m_errors; });
    m_scanner = std::make_unique<BusScanner>(m_client.get(), registry);
    m_scanner->setRange(1, 247);
    // Four times the usual wait: this part measures monitoring, and on a loaded machine the
    // simulator's answers may come later than a real drive's.
    m_scanner->setWaitMs(4 * BusScanner::defaultWaitMs(settings));
    connect(m_scanner.get(), &BusScanner::found, this,
            [this](const DeviceInfo& info) { m_drives->update(info); });
    connect(m_scanner.get(), &BusScanner::finished, this, [this] {
        if (!m_scanner->error().isEmpty())
            emit failed(QStringLiteral("model: the scan stopped: ") + m_scanner->error());
        else
            watchAll();
    });
    m_scanner->start();
    return true;
}

void ModelSoak::watchAll()
{
    for (int slave : m_drives->slaves()) {
        if (m_drives->session(slave))
            m_hub->watch(slave, &m_watcher);
    }
}

void ModelSoak::stop()
{
    // In the order the GUI tears down: views, monitors, drives, then the connection.
    m_scanner.reset();
    m_hub.reset();
    m_drives.reset();
    if (m_client)
        m_client->close();
    m_client.reset();
}

SoakPart::Totals ModelSoak::totals() const
{
    Totals t;
    t.atMs = nowMs();
    t.samples = m_samples;
    t.errors = m_errors;
    if (!m_hub)
        return t;
    const QDateTime now = QDateTime::currentDateTime();
    const QVector<int> watched = m_hub->watched();
    t.drives = int(watched.size());
    for (int slave : watched) {
        if (m_hub->freshness(slave, now) != Freshness::State::Live)
            ++t.stale;
        if (const TrendHistory* history = m_hub->history(slave))
            t.trendPoints += history->pointCount();
    }
    return t;
}

} // namespace opentop::soak
