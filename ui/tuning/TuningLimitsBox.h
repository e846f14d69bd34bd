#pragma once

#include "model/tuning/TuningRunner.h"

#include <QGroupBox>
#include <optional>

class QLabel;
class QLineEdit;

namespace opentop {

// The limits a tuning test runs within: maximum speed and current. Empty fields take the
// defaults the page gives (shown as the fields' placeholders).
class TuningLimitsBox : public QGroupBox
{
    Q_OBJECT
public:
    explicit TuningLimitsBox(QWidget* parent = nullptr);

    void setSpeedUnit(const QString& unit);
    // The defaults of empty fields (0: no current limit).
    void setDefaults(double maxSpeed, double maxCurrent);
    // `base` with the fields' limits, or nothing and *error.
    std::optional<TuningRunner::Limits> limits(TuningRunner::Limits base, QString* error) const;

private:
    QLineEdit* m_maxSpeed;
    QLineEdit* m_maxCurrent;
    QLabel* m_speedUnit;
    QString m_unit;
    double m_defaultSpeed = 0;
    double m_defaultCurrent = 0;
};

} // namespace opentop
