#pragma once

#include <QCoreApplication>
#include <QString>
#include <QVector>
#include <optional>

namespace opentop {

// The motor and load behind a simulated DC controller: a permanent-magnet DC motor with its
// winding resistance and back-EMF, fed by the controller's PWM from the supply, its current
// limited as the controller limits it, driving an inertia against viscous and Coulomb friction
// and a load torque. The speed is measured as the controller measures it: commutations counted
// over a gate time, so the measurement lags the shaft. Integrated in 1 ms steps.
class DcMotor
{
    Q_DECLARE_TR_FUNCTIONS(opentop::DcMotor)
public:
    struct Model
    {
        double supplyV = 24;             // controller supply (9–36 V)
        double resistanceOhm = 0.5;      // winding resistance
        double noLoadCommutation = 1000; // commutations per second at full duty, no friction
        double commutationsPerRev = 12;  // commutations per shaft revolution
        double inertia = 1e-4;           // kg·m², motor and load
        double viscous = 2e-5;           // N·m per rad/s
        double coulomb = 0.02;           // N·m
        double loadTorque = 0;           // N·m, opposes rotation
        double gateMs = 25;              // the controller's speed measurement window
        double tachoVoltsPerCommutation = 0.005; // external tachogenerator, V per 1/s

        // "inertia=2e-4,load=0.05": keys as named by keys(); on error nothing and *error.
        static std::optional<Model> parse(const QString& text, const Model& base, QString* error);
        static QStringList keys();
        QString toString() const;
    };

    enum class Drive
    {
        Duty,    // PWM duty, -1..1 of the supply
        Current, // a current set point (torque mode), within what the supply allows
        Brake,   // windings shorted through the brake current limit
        Coast,   // output off
        Hold     // self-locking: stopped and held
    };
    struct Input
    {
        Drive drive = Drive::Coast;
        double duty = 0;         // Drive::Duty
        double currentA = 0;     // Drive::Current, signed
        double maxCurrentA = 10; // the controller's current limit (0: none)
        double brakeCurrentA = 2;
        std::optional<double> maxCommutation; // a defect holds the shaft below this
    };

    DcMotor();
    const Model& model() const { return m_model; }
    void setModel(const Model& model) { m_model = model; }

    // One millisecond.
    void step(const Input& input);
    void reset();

    double commutation() const;         // shaft, signed 1/s
    double measuredCommutation() const; // as the controller counts it (gate average), signed
    double currentA() const { return m_current; }
    double appliedDuty() const { return m_duty; }
    double tachoVolts() const { return measuredCommutation() * m_model.tachoVoltsPerCommutation; }

private:
    double ke() const; // V per rad/s (equal to the torque constant in N·m/A)

    Model m_model;
    double m_omega = 0; // rad/s
    double m_current = 0;
    double m_duty = 0;
    QVector<double> m_gate; // shaft commutation per ms over the gate time
    int m_gateNext = 0;
    double m_gateSum = 0;
};

} // namespace opentop
