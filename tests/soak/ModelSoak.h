#pragma once

#include "tests/soak/SoakPart.h"

#include <memory>

namespace opentop {
class BusDrives;
class BusScanner;
class ModbusClient;
class MonitorHub;
} // namespace opentop

namespace opentop::soak {

// The model's way of monitoring a whole bus, in the soak's own process: a libmodbus RTU client
// on the pty, a scan of machine numbers 1..247 into BusDrives, and the MonitorHub watching
// every drive found, as the GUI's views and the command line's monitor use them.
class ModelSoak : public SoakPart
{
    Q_OBJECT
public:
    ModelSoak(int baud, int pollMs, QObject* parent = nullptr);
    ~ModelSoak() override;

    QString name() const override { return QStringLiteral("model"); }
    bool start(const QString& pty, QString* error) override;
    void stop() override;
    qint64 pid() const override { return 0; }
    Totals totals() const override;

private:
    void watchAll();

    int m_baud;
    int m_pollMs;
    std::unique_ptr<ModbusClient> m_client;
    std::unique_ptr<BusDrives> m_drives;
    std::unique_ptr<MonitorHub> m_hub;
    std::unique_ptr<BusScanner> m_scanner;
    QObject m_watcher; // watches every drive
    qint64 m_samples = 0;
    qint64 m_errors = 0;
};

} // namespace opentop::soak
