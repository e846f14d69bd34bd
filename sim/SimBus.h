#pragma once

#include "sim/FaultInjector.h"
#include "sim/SimClock.h"
#include "sim/SimDevice.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QMutex>
#include <QSet>
#include <atomic>
#include <map>
#include <memory>

namespace opentop {

struct ModbusRequest;

// What the bus does with one request frame.
struct SimOutcome
{
    QByteArray reply;         // reply ADU; empty when nobody answers
    int delayMs = 0;          // extra delay before the reply is sent (late fault)
    double turnaroundMs = -1; // the answering drive's own turnaround (a defect); < 0: the bus's
    FaultInjector::Fault fault = FaultInjector::Fault::None;
};

// An RS-485 line with simulated slaves: routes request frames by machine number, executes
// broadcasts (id 0) on every device without reply, lets DBU group members execute writes to
// their group's address silently, stays silent for unknown ids and bad CRCs, injects faults.
// Thread-safe: every entry point takes the bus lock.
class SimBus
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SimBus)
public:
    explicit SimBus(std::shared_ptr<SimClock> clock = {});
    ~SimBus();

    // "dbu200@1,dbu400@150,dcpid@7"; a drive's own line settings go in its braces with its
    // defects: "dcpid@7{format=8E1,baud=19200}" (defaults: the profile's).
    static std::shared_ptr<SimBus> fromSpec(const QString& spec, QString* error,
                                            std::shared_ptr<SimClock> clock = {});
    // A device of a family or variant id ("dbu", "dbu400", "dcpid", any profiled family).
    static std::unique_ptr<SimDevice> createDevice(const QString& type, int slave, QString* error);

    bool addDevice(std::unique_ptr<SimDevice> device, QString* error = nullptr);
    SimDevice* device(int slave) const;
    QList<SimDevice*> devices() const;
    QString spec() const;

    // `line`: the format the master sent the frame in; a device set to another does not hear
    // it (on a wire: framing or parity errors, so no answer). Unset: the bus's (setLine).
    SimOutcome handleFrame(const QByteArray& requestAdu, qint64 nowMs,
                           const LineFormat& line = LineFormat());
    SimOutcome handleFrame(const QByteArray& requestAdu)
    {
        return handleFrame(requestAdu, nowMs());
    }
    // Runs a console command on device `slave` at the clock's time.
    SimControlResult control(int slave, const QStringList& args);

    void setFaults(const FaultInjector& faults);
    // The adapter pulled out: the backend's next request fails with a port error and the
    // backend closes, as a USB adapter unplugged in use does.
    void setUnplugged(bool unplugged) { m_unplugged = unplugged; }
    bool isUnplugged() const { return m_unplugged; }
    // The line's settings; devices whose settings in force differ do not hear the frames.
    // The devices present are configured to match, as an installer would have done.
    void setLine(int baud, char parity);
    int lineBaud() const { return m_lineBaud; }
    // Gives device `slave` line settings of its own (validated against its profile's formats
    // and rates), which setLine() then leaves alone. `format` "8E1", `baud` "19200"; empty
    // for the profile's default.
    bool setOwnLine(int slave, const QString& format, const QString& baud, QString* error);
    bool hasOwnLine(int slave) const { return m_ownLine.contains(slave); }

    SimClock& clock() const { return *m_clock; }
    qint64 nowMs() const { return m_clock->nowMs(); }
    QMutex& mutex() const { return m_mutex; }

    // Parses a CRC-checked request ADU as far as it goes; rawData holds the bytes after the
    // function code, so that devices can check the structure themselves.
    static bool decodeRequest(const QByteArray& adu, ModbusRequest* request);

private:
    bool hears(const SimDevice& device, const LineFormat& sent) const;
    // The braces' items of `entry`: its own line settings applied, the rest (defects) left.
    static bool takeLineItems(SimBus& bus, int slave, QString* items, QString* error);

    std::shared_ptr<SimClock> m_clock;
    std::map<int, std::unique_ptr<SimDevice>> m_devices;
    FaultInjector m_faults;
    int m_lineBaud = 0;
    char m_lineParity = 0;
    QSet<int> m_ownLine;
    mutable QMutex m_mutex;
    std::atomic<bool> m_unplugged{false};
};

} // namespace opentop
