#pragma once

#include <QGroupBox>
#include <optional>

class QDoubleSpinBox;
class QLabel;

namespace opentop {

struct MonitorSample;
struct ParameterMeta;

// A speed measured as a frequency (the DC controller's commutations per second) becomes r/min
// only with the motor's commutations per revolution, which the controller does not know: the
// user says, and it is remembered for this machine number.
class MotorSpeedBox : public QGroupBox
{
    Q_OBJECT
public:
    // `speed`: the frequency parameter (unit "1/s") of the drive at `slave`.
    MotorSpeedBox(const ParameterMeta& speed, int slave, QWidget* parent = nullptr);

    static bool appliesTo(const ParameterMeta* speed);
    void setCommutationsPerRevolution(double count);
    void showSample(const MonitorSample& sample);
    QString speedText() const; // "1500 r/min", or what is missing

private:
    void updateText();

    QString m_speedName;
    int m_slave;
    QDoubleSpinBox* m_commutations;
    QLabel* m_speed;
    bool m_sampled = false;
    std::optional<double> m_frequency; // of the last sample; none when it was not read
};

} // namespace opentop
