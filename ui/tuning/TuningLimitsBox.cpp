#include "ui/tuning/TuningLimitsBox.h"

#include "ui/tuning/NumberField.h"

#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>

namespace opentop {

TuningLimitsBox::TuningLimitsBox(QWidget* parent)
    : QGroupBox(tr("Limits"), parent)
    , m_maxSpeed(NumberField::make(QStringLiteral("maxSpeed"), QString(), this))
    , m_maxCurrent(NumberField::make(QStringLiteral("maxCurrent"), QString(), this))
    , m_speedUnit(new QLabel(this))
{
    m_maxSpeed->setToolTip(tr("Beyond it the motor is stopped at once. Empty: 125 % of the step "
                              "test's highest speed, 150 % of the autotune's speed"));
    m_maxCurrent->setToolTip(tr("Beyond it the motor is stopped at once. Empty: 1.2 × the "
                                "drive's maximum current"));
    auto* form = new QFormLayout(this);
    form->addRow(tr("Max. speed:"), NumberField::withUnit(m_maxSpeed, m_speedUnit, this));
    form->addRow(tr("Max. current:"),
                 NumberField::withUnit(m_maxCurrent, new QLabel(tr("A"), this), this));
}

void TuningLimitsBox::setSpeedUnit(const QString& unit)
{
    m_unit = unit;
    m_speedUnit->setText(unit);
}

void TuningLimitsBox::setDefaults(double maxSpeed, double maxCurrent)
{
    m_defaultSpeed = maxSpeed;
    m_defaultCurrent = maxCurrent;
    m_maxSpeed->setPlaceholderText(tr("auto: %1").arg(NumberField::text(maxSpeed)));
    m_maxCurrent->setPlaceholderText(
        maxCurrent > 0 ? tr("auto: %1").arg(NumberField::text(maxCurrent)) : tr("none"));
}

std::optional<TuningRunner::Limits> TuningLimitsBox::limits(TuningRunner::Limits base,
                                                            QString* error) const
{
    const std::optional<double> maxSpeed = NumberField::value(m_maxSpeed);
    const std::optional<double> maxCurrent = NumberField::value(m_maxCurrent);
    if (!m_maxSpeed->text().trimmed().isEmpty() && (!maxSpeed || *maxSpeed <= 0)) {
        *error = tr("Enter a speed limit above 0 %1, or leave it empty.").arg(m_unit);
        return std::nullopt;
    }
    if (!m_maxCurrent->text().trimmed().isEmpty() && (!maxCurrent || *maxCurrent <= 0)) {
        *error = tr("Enter a current limit above 0 A, or leave it empty.");
        return std::nullopt;
    }
    base.maxSpeed = maxSpeed.value_or(m_defaultSpeed);
    base.maxCurrent = maxCurrent.value_or(m_defaultCurrent);
    return base;
}

} // namespace opentop
