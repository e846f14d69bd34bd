#pragma once

#include "model/profile/ParamValue.h"
#include "model/profile/Profile.h"
#include "model/profile/ValueContext.h"
#include "model/session/GroupReach.h"
#include "model/session/ReachedResult.h"
#include "transport/ModbusRequest.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QVector>
#include <functional>
#include <memory>

namespace opentop {

class ModbusClient;
struct ModbusResult;

// One drive on the bus, as the rest of the program works with it: parameters by name, values
// validated against the profile before any frame is built, writes read back and verified, and
// device errors explained (for the DBU, the communication error register is read and decoded).
//
// Values read from the device update the cache and emit valueUpdated(), never a write: only
// write() sends values, and only ones the caller asked for.
//
// A write reaches other drives too when they execute what is sent to this one (communication
// group children, told by a GroupReach): each of them validates the value before anything is
// sent, and each is read back afterwards (ReachedDrives); the write is verified only when every
// drive it reached holds the value.
class DeviceSession : public QObject
{
    Q_OBJECT
public:
    struct Outcome
    {
        bool ok = false;
        QString parameter;
        ParamValue value;    // the value read (or read back after a write)
        QString error;       // what went wrong, for people
        QString deviceError; // decoded device error register, when there is one
        int deviceCode = -1; // its code (the profile's code table), -1 when there is none
        // What the device's error code means and what to do (the profile's words), when known.
        QString explanation;
        // Accepted but outside the recommended range: ValueCodec::recommendationWarning.
        QString warning;
        bool sent = false;     // whether anything reached the wire (false: refused before)
        bool verified = false; // a write was read back and matched, on every drive it reached
        bool mismatch = false; // a write was read back and differed (here or on a drive reached)
        // A write whose frame may have reached the drive but whose reply never came (the port
        // vanished, a timeout, a garbled reply): the drive may or may not hold the value.
        bool unconfirmed = false;
        // The other drives the write reached (communication group children), each read back.
        QVector<ReachedResult> reached;
        // Written and held here, but not verified on every drive it reached: which, and why.
        QString notVerified;
    };
    using Done = std::function<void(const Outcome&)>;

    struct ReadManyOutcome
    {
        QHash<QString, Outcome> results; // by parameter name
        QStringList order;               // names in the order asked
        int requests = 0;                // requests sent, fallbacks included
        int failed = 0;                  // parameters that could not be read
    };
    using ManyDone = std::function<void(const ReadManyOutcome&)>;

    struct WriteOptions
    {
        // Commands that move a motor, reset, erase, initialise, store or change communication
        // are refused unless the caller states that the user asked for exactly this.
        bool explicitCommand = false;
        bool verify = true;
        // Settings written in the same operation, after this one: a setting whose allowed
        // values depend on this one may be among them (DependentValues).
        QStringList companions;
    };

    DeviceSession(ModbusClient* client, const Profile& profile, int slave, const QString& variant,
                  QObject* parent = nullptr);

    const Profile& profile() const { return m_profile; }
    int slave() const { return m_slave; }
    QString variant() const { return m_variant; }
    void setVariant(const QString& variant) { m_variant = variant; }
    QString machineName() const { return m_machineName; } // "Infeed conveyor 3" (DriveName)
    void setMachineName(const QString& name) { m_machineName = name; }
    // Messages name parameters by the profile's label (windows) or the internal name (default).
    void setLabelsInMessages(bool labels) { m_labelsInMessages = labels; }
    // A parameter as messages name it (see setLabelsInMessages).
    QString nameFor(const QString& parameter) const;
    ModbusClient* client() const { return m_client; }

    // Who tells which other drives execute what is sent to this one (none: only this one).
    void setGroupReach(GroupReach* reach) { m_reach = reach; }
    // The other drives a frame to this one reaches, as the GroupReach knows them.
    QVector<DeviceSession*> reachedDrives() const
    {
        return m_reach ? m_reach->reachedBy(m_slave) : QVector<DeviceSession*>();
    }
    // Why a drive that a write of `registers` to `name` also reaches would refuse it, naming it
    // and what it allows; empty when all allow it or none is reached. With those drives' values
    // as known: for checks before a question; write() checks again, reading what is missing.
    QString reachedProblem(const QString& name, const QVector<quint16>& registers) const;

    // The variant and the cached raw values other parameters' allowed sets depend on.
    ValueContext context() const;
    bool hasCached(const QString& name) const { return m_cache.contains(name); }
    QVector<quint16> cachedRegisters(const QString& name) const { return m_cache.value(name); }
    ParamValue cachedValue(const QString& name) const;

    void read(const QString& name, Done done);
    // Reads several parameters in as few requests as the device allows (ReadPlanner), falling
    // back to one request per parameter where the device refuses a block.
    // `priority` Poll lets user requests overtake background polling.
    void readMany(const QStringList& names, ManyDone done,
                  ModbusRequest::Priority priority = ModbusRequest::Priority::Normal);
    // Validates `text` (engineering units or enumeration label), writes, reads back.
    void write(const QString& name, const QString& text, const WriteOptions& options, Done done);
    // Stores registers obtained elsewhere (a block read) as device values.
    void acceptRegisters(const QString& name, const QVector<quint16>& registers);
    // Stores what the identify read returned (DeviceInfo::identifyRegisters): the parameters of
    // the profile's identify block, read moments ago.
    void acceptIdentification(const QVector<quint16>& identifyRegisters);

signals:
    // A value read from the device (never an echo of a user edit).
    void valueUpdated(const QString& name, const opentop::ParamValue& value);
    // The drive acknowledged a write of `name` (before it is read back). Drives of a
    // communication group whose parent this is executed it too (BusGroupTracker).
    void written(const QString& name);

private:
    const ParameterMeta* lookup(const QString& name, Outcome* outcome) const;
    friend class BlockReader; // readMany's blocks name parameters as lookup() does
    // `busyRetries`: how often a setting is sent again when the drive refused it only because
    // it was busy (its communication error register says so: nothing was executed).
    // A setting with a `writeBlock` reads the rest of its block first and goes as that frame.
    void send(const ParameterMeta* meta, const QVector<quint16>& registers,
              const WriteOptions& options, Outcome outcome, Done done, int busyRetries = 3);
    void submitWrite(const ParameterMeta* meta, const ModbusRequest& request,
                     const QVector<quint16>& registers, const WriteOptions& options,
                     Outcome outcome, Done done, int busyRetries);
    // Reads the drive's reason for an exception; `onBusy`, when set, runs instead of `done`
    // when the reason is one to send the request again for.
    void explainFailure(const ModbusResult& result, Outcome outcome, Done done,
                        std::function<void()> onBusy = {});
    void verifyWrite(const ParameterMeta& meta, const QVector<quint16>& written, Outcome outcome,
                     Done done);

    ModbusClient* m_client;
    const Profile& m_profile;
    int m_slave;
    QString m_variant;
    QString m_machineName;
    bool m_labelsInMessages = false;
    QHash<QString, QVector<quint16>> m_cache;
    QPointer<GroupReach> m_reach;
};

} // namespace opentop
