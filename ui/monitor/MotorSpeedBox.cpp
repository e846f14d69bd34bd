#include "ui/monitor/MotorSpeedBox.h"

#include "model/monitor/DeviceMonitor.h"
#include "model/profile/ParameterMeta.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>

namespace opentop {

namespace {

QString settingsKey(int slave)
{
    return QStringLiteral("monitor/commutationsPerRevolution/%1").arg(slave);
}

} // namespace

MotorSpeedBox::MotorSpeedBox(const ParameterMeta& speed, int slave, QWidget* parent)
    : QGroupBox(tr("Motor speed"), parent)
    , m_speedName(speed.name)
    , m_slave(slave)
    , m_commutations(new QDoubleSpinBox(this))
    , m_speed(new QLabel(QStringLiteral("—"), this))
{
    auto* form = new QFormLayout(this);
    m_commutations->setObjectName(QStringLiteral("commutationsPerRevolution"));
    m_commutations->setRange(0, 1000);
    m_commutations->setDecimals(0);
    m_commutations->setSpecialValueText(tr("not set"));
    m_commutations->setToolTip(tr("Commutations per motor revolution (a motor property, "
                                  "see its data sheet). r/min = %1 ÷ this × 60.")
                                   .arg(speed.label));
    m_commutations->setValue(QSettings().value(settingsKey(m_slave), 0).toDouble());
    form->addRow(tr("Commutations per revolution"), m_commutations);
    // As large as the monitor page's other speeds.
    QFont f = m_speed->font();
    f.setPointSizeF(f.pointSizeF() * 1.3);
    f.setBold(true);
    m_speed->setFont(f);
    m_speed->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // "set the commutations per revolution" in large type wraps in a narrow column (a laptop
    // with a dock open) instead of widening the values past the page.
    m_speed->setWordWrap(true);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    form->addRow(tr("Motor speed"), m_speed);
    connect(m_commutations, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        QSettings().setValue(settingsKey(m_slave), v);
        if (m_sampled)
            updateText();
    });
}

bool MotorSpeedBox::appliesTo(const ParameterMeta* speed)
{
    return speed && speed->spec.unit == QLatin1String("1/s");
}

void MotorSpeedBox::setCommutationsPerRevolution(double count)
{
    m_commutations->setValue(count);
}

void MotorSpeedBox::showSample(const MonitorSample& s)
{
    const MonitorValue* v = s.find(m_speedName);
    m_sampled = true;
    m_frequency = v && v->value.valid ? std::optional<double>(v->value.number) : std::nullopt;
    updateText();
}

void MotorSpeedBox::updateText()
{
    const double perRevolution = m_commutations->value();
    if (perRevolution <= 0)
        m_speed->setText(tr("set the commutations per revolution"));
    else if (!m_frequency)
        m_speed->setText(QStringLiteral("—"));
    else
        m_speed->setText(tr("%1 r/min").arg(*m_frequency / perRevolution * 60.0, 0, 'f', 0));
}

QString MotorSpeedBox::speedText() const
{
    return m_speed->text();
}

} // namespace opentop
