#pragma once

#include "cli/BusDriveList.h"
#include "cli/ExitCode.h"
#include "model/bus/BusGroups.h"
#include "model/session/DeviceInfo.h"
#include "model/session/GroupReach.h"
#include "model/traffic/TrafficDescriber.h"
#include "transport/ConnectionSettings.h"

#include <QCommandLineParser>
#include <QHash>
#include <QObject>
#include <QTextStream>
#include <functional>
#include <memory>

namespace opentop {

class DeviceSession;
class ModbusClient;
class SimBus;
class TrafficLog;

// What every command works with: the parsed command line, the output streams, the bus
// connection, identified devices, and a synchronous way to wait for asynchronous model work
// that Ctrl-C can interrupt between transactions. The GroupReach of every session it makes: the
// groups found before a write (GroupCheck) tell each session which drives execute its writes too.
class CliContext : public GroupReach
{
    Q_OBJECT
public:
    CliContext(const QCommandLineParser& parser, QTextStream& out, QTextStream& err,
               QObject* parent = nullptr);
    ~CliContext() override;

    const QCommandLineParser& parser() const { return m_parser; }
    QTextStream& out() { return m_out; }
    QTextStream& err() { return m_err; }
    bool json() const { return m_parser.isSet(QStringLiteral("json")); }

    // Opens the bus named by the connection options; prints the reason and returns false if it
    // cannot. Commands that need no bus (ports, params) never call it.
    bool connectBus();
    ModbusClient* client() const { return m_client.get(); }
    SimBus* simBus() const { return m_simBus.get(); }
    TrafficLog* trafficLog() const { return m_log.get(); }
    const ConnectionSettings& settings() const { return m_settings; }
    // Machine numbers the connection already knows (a simulated bus's device list).
    QVector<int> knownSlaves() const { return m_knownSlaves; }

    // The drives on the bus for the group check (BusDriveList: --bus-drives LIST, else
    // OPENTOP_BUS_DRIVES, else the simulated bus's list, else the last scan's drives); nullopt
    // (with *error) when the list given is malformed.
    std::optional<BusDriveList> busDrives(QString* error);

    // The groups found before a write: --trace then shows who else a write to a parent reaches,
    // and a session's writes are validated by and read back from its children (GroupReach).
    void setGroups(const BusGroups& groups);
    QVector<DeviceSession*> reachedBy(int slave) const override;

    // Identifies `slave` (once) and returns its session; nullptr with *error when nobody
    // answers or the device is not a profiled family. Applies --variant and the simulated
    // bus's variants where the device does not report its own.
    DeviceSession* session(int slave, QString* error);
    DeviceInfo identify(int slave);
    // The variant given for `slave` (--variant VARIANT or --variant ID=VARIANT,...).
    QString assignedVariant(int slave, const QString& family) const;
    // The variant a person gave with --variant for this drive (never the simulator's): none
    // when --variant names nothing for it; "" when it names a variant of another family.
    std::optional<QString> givenVariant(int slave, const QString& family) const;

    // The bus the connection options name, as BusMemory keeps it ("serial:/dev/ttyUSB0"),
    // without opening it; empty with *error when the options are wrong or missing.
    QString busKey(QString* error) const;
    // The names given to this bus's machines (`name`, or the window), read once.
    QHash<int, QString> machineNames();

    // Runs `start`, which must eventually call the `finish` it is given, and processes events
    // until then. Returns false when Ctrl-C arrived first (queued requests are cancelled).
    // Callbacks must capture `finish` by value: `start` returns before they run.
    bool wait(const std::function<void(std::function<void()> finish)>& start);
    bool interrupted() const;
    // Parses "1,2,5-7" (machine numbers 1–247).
    static std::optional<QVector<int>> parseIds(const QString& text, QString* error);

    // The first wrong item of a --variant value (VARIANT or ID=VARIANT,...), empty when right.
    static QString variantError(const QString& text);
    // `type` ("dbu400") as a variant of `family`, or "".
    static QString fittingVariant(const QString& type, const QString& family);
    // True when the connection options were wrong or missing (the exit code is then 2).
    bool usageError() const { return m_usageError; }

    static void installInterruptHandler();

private:
    const QCommandLineParser& m_parser;
    QTextStream& m_out;
    QTextStream& m_err;
    ConnectionSettings m_settings;
    std::unique_ptr<TrafficLog> m_log;
    TrafficDescriber m_describer{[](int) { return nullptr; }}; // adds only who else a write reaches
    std::shared_ptr<SimBus> m_simBus;
    std::unique_ptr<ModbusClient> m_client;
    QVector<int> m_knownSlaves;
    QHash<int, QString> m_simTypes;
    QHash<int, DeviceSession*> m_sessions;
    QHash<int, DeviceInfo> m_identified;
    std::optional<QHash<int, QString>> m_machineNames;
    BusGroups m_groups;
    bool m_usageError = false;
};

} // namespace opentop
