#pragma once

#include "model/profile/Profile.h"
#include "model/profile/ValueContext.h"
#include "sim/SimDefects.h"
#include "sim/SimRegisters.h"
#include "transport/LineFormat.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QHash>
#include <QStringList>
#include <optional>

namespace opentop {

struct ModbusRequest;

// Why a simulated device refuses a request; each family maps it to its exception code.
enum class SimError
{
    None,
    IllegalFunction, // function code not supported
    IllegalAddress,  // no such register for this function
    BadFormat,       // count 0 or too large, byte count wrong, frame too short
    ReadOnly,        // write to a register that can only be read
    Refused,         // command not possible in the current state
    OutOfRange,      // value outside the allowed set
    Busy,            // internal processing (fault injection)
    Prohibited,      // forbidden by a lock
};

// What a console or test command produced.
struct SimControlResult
{
    bool ok = true;
    QString text;
};

// A simulated slave: a register memory laid out by the device's profile, the generic Modbus
// request handling (exceptions, validation against the profile, temporary settings that need a
// store command) and hooks through which a family adds its behaviour. Not thread-safe: the bus
// serialises access.
class SimDevice
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SimDevice)
public:
    SimDevice(const Profile& profile, const QString& variant, int slave);
    virtual ~SimDevice();
    SimDevice(const SimDevice&) = delete;
    SimDevice& operator=(const SimDevice&) = delete;

    int slave() const { return m_slave; }
    const Profile& profile() const { return m_profile; }
    QString variant() const { return m_variant; }
    QString type() const { return m_variant.isEmpty() ? m_profile.family : m_variant; }

    // Executes `request` at time `nowMs`. Returns the reply ADU, or nothing for broadcasts, for
    // group copies (`addressedDirectly` false) and for requests a device does not answer.
    QByteArray handle(const ModbusRequest& request, qint64 nowMs, bool addressedDirectly);
    // The reply of a device too busy to execute `request` (fault injection).
    QByteArray busyReply(const ModbusRequest& request, qint64 nowMs);
    // Text backdoor used by the console and tests: get, set, power-cycle and family commands.
    SimControlResult control(const QStringList& args, qint64 nowMs);
    // Power off and on: settings stay, temporary settings and running state are lost.
    void powerCycle(qint64 nowMs);
    // Runs the simulation up to `nowMs` and updates the status registers.
    void advance(qint64 nowMs);

    // The virtual address (DBU communication group) this device also executes writes for.
    virtual std::optional<int> groupAddress() const { return std::nullopt; }
    // One line for the console's list.
    virtual QString stateText() const;
    // Serial settings in force since the last power cycle (0 / '\0' when the device has none).
    virtual int lineBaud() const { return 0; }
    virtual char lineParity() const { return 0; }
    virtual int lineStopBits() const { return 1; }
    // The three as one format; unset when the device has none (it hears every frame).
    LineFormat lineFormat() const;
    // Sets the device's stored serial settings to the line's, as an installer would.
    virtual void configureLine(int baud, char parity);

    const ParameterMeta* param(const QString& name) const { return m_profile.parameter(name); }
    std::optional<double> raw(const QString& name) const;
    void setRaw(const QString& name, double raw); // no validation
    quint16 reg(quint8 function, quint16 address) const;
    void setReg(quint8 function, quint16 address, quint16 value); // no validation
    ValueContext context() const;
    SimError lastError() const { return m_lastError; }
    const SimRegisters& memory() const { return m_regs; }

    // Simulated defects (SimDefectSpec): `spec` on top of the present ones; on error nothing
    // changes and *error names what is allowed.
    bool addDefects(const SimDefectSpec& spec, QString* error);
    const SimDefects& defects() const { return m_defects; }

    // "1500", "-3", "0x05DC", "05DCh".
    static std::optional<qint64> parseNumber(const QString& text);
    static SimControlResult fail(const QString& text) { return {false, text}; }

protected:
    // Function codes this device answers; others get IllegalFunction.
    virtual bool supportsFunction(quint8 function) const;
    virtual quint8 exceptionCode(SimError error) const;
    // Called for every refused request, replied or not.
    virtual void recordError(SimError error);
    // Function codes other than 03/04/06/10. Returns the reply PDU, or sets *error.
    virtual QByteArray handleOther(const ModbusRequest& request, qint64 nowMs, SimError* error);
    // A multi-register parameter may be written in parts (06 to one half).
    virtual bool allowsPartialWrite(const ParameterMeta&) const { return false; }
    // A register without parameter that a 0x10 may span (its value is ignored).
    virtual bool acceptsGapWrite(quint16) const { return false; }
    // Refuses a valid value in the current state (Refused, Prohibited).
    virtual SimError checkWrite(const ParameterMeta&, double, qint64) { return SimError::None; }
    // Effects of an accepted write, after the registers hold the new values. The base stores
    // the parameters whose storeWith names `meta`.
    virtual void afterWrite(const ParameterMeta& meta, double raw, qint64 nowMs);
    // Called once per accepted 06/0x10 after afterWrite for each parameter.
    virtual void afterBlockWrite(quint8, quint16, int, qint64) {}
    // Called for every frame this device executes (addressed, group or broadcast).
    virtual void frameSeen(qint64) {}
    virtual void step(qint64, int) {} // simulation step ending at nowMs, dtMs long
    // True while nothing moves or counts down: a long silence is then one step, so that an
    // idle device answers as fast after an hour as after a second.
    virtual bool quiescent() const { return false; }
    virtual void refreshStatus(qint64) {} // status registers from the state
    virtual void onPowerCycle(qint64) {}
    virtual SimControlResult controlCommand(const QStringList& args, qint64 nowMs);
    virtual char stringPad() const { return '\0'; }

    SimRegisters& registers() { return m_regs; }
    const SimRegisters& registers() const { return m_regs; }
    double rawOf(const QString& name) const; // 0 when the profile has no such parameter
    void setRawOf(const QString& name, double raw);
    // Back to the profile's default (settings without a default keep their value).
    void applyDefault(const ParameterMeta& meta);

private:
    friend class SimRequestHandler; // the request handling calls the hooks above
    ValueContext contextOf(const SimRegisters& regs) const;
    SimControlResult defectCommand(const QStringList& args);

    SimDefects m_defects;
    std::optional<quint16> m_trueFirmware;            // the version before a firmware defect
    QHash<QString, QVector<quint16>> m_powerOnValues; // nostore: what a power cycle brings back

    Profile m_profile;
    QString m_variant;
    int m_slave;
    SimRegisters m_regs;
    qint64 m_lastAdvanceMs = -1;
    SimError m_lastError = SimError::None;
};

} // namespace opentop
