#pragma once

#include "sim/DbuMotor.h"
#include "sim/DbuTerminals.h"
#include "sim/SimCodeRecords.h"
#include "sim/SimDevice.h"

#include <optional>

namespace opentop {

// A TROY DBU brushless drive (manual chapters 7–13): separate 03/04 spaces, exceptions with the
// communication error register 0x007B, communication / I/O priority, SPno1..8 speed presets with
// ramps, load, alarms and warnings with their 15-entry stacks, group communication.
class DbuSimDevice : public SimDevice
{
    Q_DECLARE_TR_FUNCTIONS(opentop::DbuSimDevice)
public:
    DbuSimDevice(const Profile& profile, const QString& variant, int slave);

    std::optional<int> groupAddress() const override;
    QString stateText() const override;
    int lineBaud() const override;
    char lineParity() const override { return 'N'; }
    void configureLine(int baud, char parity) override;

    double speed() const { return m_motor.speed(); } // signed r/min, CCW negative
    int alarm() const { return m_alarm; }
    bool isOnline() const { return !m_offline; }
    double load() const { return m_motor.load(); }

    static int baudForRateCode(int code);

protected:
    bool supportsFunction(quint8 function) const override;
    quint8 exceptionCode(SimError error) const override;
    void recordError(SimError error) override;
    SimError checkWrite(const ParameterMeta& meta, double raw, qint64 nowMs) override;
    void afterWrite(const ParameterMeta& meta, double raw, qint64 nowMs) override;
    void step(qint64 nowMs, int dtMs) override;
    void refreshStatus(qint64 nowMs) override;
    void onPowerCycle(qint64 nowMs) override;
    SimControlResult controlCommand(const QStringList& args, qint64 nowMs) override;
    char stringPad() const override { return ' '; }

private:
    struct Command
    {
        bool run = false;
        int spno = 0; // 0..7
        bool ccw = false;
    };
    bool communicationControl() const;
    Command currentCommand() const;
    double targetMagnitude(const Command& command) const;
    double rampRate(int spno, bool accelerate) const;
    void raiseAlarm(int code);
    bool alarmResettable() const;
    SimControlResult consoleCode(const QStringList& args, bool alarm);

    DbuMotor m_motor;
    SimCodeRecords m_alarms;
    SimCodeRecords m_warnings;
    DbuTerminals m_terminals;
    Command m_command;   // what the drive executes now
    double m_target = 0; // signed r/min
    bool quiescent() const override;
    bool m_started = false;
    bool m_offline = false;
    bool m_ignoreStop = false;
    std::optional<int> m_directionOverride;
    int m_alarm = 0;
    int m_vr = 500;
    int m_loadOffset = 0;
    int m_inputs = 0;
    int m_previousInputs = 0;
    int m_consoleWarning = 0;
    int m_activeRate = 2;
};

} // namespace opentop
