#pragma once

#include "sim/DcMotor.h"
#include "sim/DcSpeedLoop.h"
#include "sim/SimDevice.h"

namespace opentop {

// The 9–36 V / 20 A DC motor controller with PID speed control (its manual, section 1): 03, 06,
// 10 and 2B/0E, exception 0x40 for locked serial settings, the speed command per speed mode
// driving a simulated motor and load (DcMotor) — open-loop PWM, current, or the speed PID
// (DcSpeedLoop) with the coefficients in its registers —, temporary configuration until stored,
// braking on communication loss.
class DcPidSimDevice : public SimDevice
{
    Q_DECLARE_TR_FUNCTIONS(opentop::DcPidSimDevice)
public:
    enum class Drive
    {
        Idle,
        Running,
        Braking,
        Coasting,
        Locked
    };

    DcPidSimDevice(const Profile& profile, const QString& variant, int slave);

    QString stateText() const override;
    int lineBaud() const override { return m_lineBaud; }
    char lineParity() const override { return m_lineParity; }
    // The manual's check mode 0 is "no parity, 2 stop bits".
    int lineStopBits() const override { return m_lineParity == 'N' ? 2 : 1; }
    void configureLine(int baud, char parity) override;

    Drive drive() const { return m_drive; }
    double duty() const { return m_motor.appliedDuty(); } // -1 .. 1 of full output
    const DcMotor& motor() const { return m_motor; }
    void setMotorModel(const DcMotor::Model& model) { m_motor.setModel(model); }

    static char parityForCode(int code);

protected:
    bool supportsFunction(quint8 function) const override;
    quint8 exceptionCode(SimError error) const override;
    QByteArray handleOther(const ModbusRequest& request, qint64 nowMs, SimError* error) override;
    bool allowsPartialWrite(const ParameterMeta& meta) const override;
    bool acceptsGapWrite(quint16 address) const override;
    SimError checkWrite(const ParameterMeta& meta, double raw, qint64 nowMs) override;
    void afterWrite(const ParameterMeta& meta, double raw, qint64 nowMs) override;
    void afterBlockWrite(quint8 function, quint16 address, int count, qint64 nowMs) override;
    void frameSeen(qint64 nowMs) override { m_lastFrameMs = nowMs; }
    void step(qint64 nowMs, int dtMs) override;
    void refreshStatus(qint64 nowMs) override;
    void onPowerCycle(qint64 nowMs) override;
    SimControlResult controlCommand(const QStringList& args, qint64 nowMs) override;

private:
    // One millisecond of the controller and its motor.
    void stepMotor();
    DcSpeedLoop::Gains gains() const;
    SimControlResult motorCommand(const QStringList& args);
    QByteArray identification(quint8 readCode, quint8 objectId, SimError* error) const;
    void takeLineSettings();
    // Signed commutations per second: the output's, unless a defect holds the motor.
    double turning() const;
    // The stall stop (config.stall_time) and an alarm defect: brakes the motor.
    void stallProtection(int dtMs);

    DcMotor m_motor;
    DcSpeedLoop m_loop;
    Drive m_drive = Drive::Idle;
    int m_command = 0;
    qint64 m_lastFrameMs = 0;
    int m_inputs = 0; // bit0 SQ1, bit1 SQ2, bit2 DE
    int m_loadOffset = 0;
    int m_lineBaud = 0;
    char m_lineParity = 0;
    qint64 m_runningMs = 0; // since the speed command, for an alarm defect
    qint64 m_stalledMs = 0;
    bool m_stallStopped = false; // stopped by the stall stop until the next speed command
};

} // namespace opentop
