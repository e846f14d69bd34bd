#include "ui/connection/SerialLineFields.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>

namespace opentop {

namespace {

using Rs485 = ConnectionSettings::Rs485;

QString key(const char* name)
{
    return QStringLiteral("connection/") + QLatin1String(name);
}

} // namespace

SerialLineFields::SerialLineFields(QWidget* page, QFormLayout* form)
    : QObject(page)
{
    m_direction = new QComboBox(page);
    m_direction->setObjectName(QStringLiteral("rs485"));
    m_direction->addItem(tr("Adapter switches itself"), int(Rs485::Off));
    m_direction->addItem(tr("Auto (kernel, else RTS)"), int(Rs485::Auto));
    m_direction->addItem(tr("Kernel RS-485 mode"), int(Rs485::Kernel));
    m_direction->addItem(tr("RTS from the program"), int(Rs485::Rts));
    m_direction->setToolTip(
        tr("Who switches the RS-485 transceiver between sending and receiving. USB–RS-485 "
           "adapters do it themselves; on-board RS-485 ports need the driver's RS-485 mode "
           "(kernel) or RTS switched by the program. The status bar says what the driver "
           "accepted."));
    form->addRow(tr("RS-485 d&irection:"), m_direction);

    auto* rtsRow = new QHBoxLayout;
    m_polarity = new QComboBox(page);
    m_polarity->setObjectName(QStringLiteral("rtsPolarity"));
    m_polarity->addItem(tr("high while sending"), true);
    m_polarity->addItem(tr("low while sending"), false);
    m_polarity->setToolTip(tr("The RTS level that enables the transceiver's driver"));
    m_delay = new QSpinBox(page);
    m_delay->setObjectName(QStringLiteral("rtsDelay"));
    m_delay->setRange(0, ConnectionSettings::kMaxRtsDelayUs);
    m_delay->setSingleStep(100);
    m_delay->setPrefix(tr("delay "));
    m_delay->setSuffix(tr(" µs"));
    m_delay->setSpecialValueText(tr("default delay"));
    m_delay->setToolTip(tr("Before and after sending. Default: the driver's own, or one "
                           "character time from the program; the kernel rounds up to whole ms."));
    rtsRow->addWidget(m_polarity, 1);
    rtsRow->addWidget(m_delay, 1);
    // A row holding a layout gets no buddy from QFormLayout, and "&" would show.
    auto* rtsLabel = new QLabel(tr("RTS le&vel:"), page);
    rtsLabel->setBuddy(m_polarity);
    form->addRow(rtsLabel, rtsRow);

    m_lowLatency = new QCheckBox(tr("&Low latency (no 16 ms hold-back in USB adapters)"), page);
    m_lowLatency->setObjectName(QStringLiteral("lowLatency"));
    m_lowLatency->setToolTip(
        tr("Asks the driver to pass received bytes on at once. Many USB–serial chips otherwise "
           "hold them for up to 16 ms, which slows scans and polling."));
    form->addRow(QString(), m_lowLatency);

    connect(m_direction, qOverload<int>(&QComboBox::currentIndexChanged), this,
            &SerialLineFields::updateEnabled);
    setSettings(ConnectionSettings());
}

void SerialLineFields::updateEnabled()
{
    // Level and delay mean nothing while the adapter switches by itself.
    const bool switched = Rs485(m_direction->currentData().toInt()) != Rs485::Off;
    m_polarity->setEnabled(switched);
    m_delay->setEnabled(switched);
}

void SerialLineFields::setSettings(const ConnectionSettings& s)
{
    const int direction = m_direction->findData(int(s.rs485));
    m_direction->setCurrentIndex(std::max(0, direction));
    m_polarity->setCurrentIndex(s.rtsHighWhileSending ? 0 : 1);
    m_delay->setValue(s.rtsDelayUs);
    m_lowLatency->setChecked(s.lowLatency);
    updateEnabled();
}

void SerialLineFields::applyTo(ConnectionSettings* s) const
{
    s->rs485 = Rs485(m_direction->currentData().toInt());
    s->rtsHighWhileSending = m_polarity->currentData().toBool();
    s->rtsDelayUs = m_delay->value();
    s->lowLatency = m_lowLatency->isChecked();
}

void SerialLineFields::recall(const QSettings& stored, ConnectionSettings* s)
{
    ConnectionSettings::Rs485 mode = s->rs485;
    if (ConnectionSettings::rs485FromName(stored.value(key("rs485")).toString(), &mode))
        s->rs485 = mode;
    s->rtsHighWhileSending =
        stored.value(key("rtsHighWhileSending"), s->rtsHighWhileSending).toBool();
    s->rtsDelayUs = stored.value(key("rtsDelayUs"), s->rtsDelayUs).toInt();
    s->lowLatency = stored.value(key("lowLatency"), s->lowLatency).toBool();
}

void SerialLineFields::remember(QSettings& stored, const ConnectionSettings& s)
{
    stored.setValue(key("rs485"), ConnectionSettings::rs485Name(s.rs485));
    stored.setValue(key("rtsHighWhileSending"), s.rtsHighWhileSending);
    stored.setValue(key("rtsDelayUs"), s.rtsDelayUs);
    stored.setValue(key("lowLatency"), s.lowLatency);
}

} // namespace opentop
