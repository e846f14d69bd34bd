#pragma once

#include "transport/ConnectionSettings.h"

#include <QObject>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QSettings;
class QSpinBox;

namespace opentop {

// The serial page's RS-485 direction control (who switches the transceiver, RTS level and
// delay, enabled only where they apply) and low-latency rows, added to the page's form; their
// remembered values sit under the dialog's "connection/" keys.
class SerialLineFields : public QObject
{
    Q_OBJECT
public:
    SerialLineFields(QWidget* page, QFormLayout* form);

    void setSettings(const ConnectionSettings& settings);
    void applyTo(ConnectionSettings* settings) const;

    static void recall(const QSettings& stored, ConnectionSettings* settings);
    static void remember(QSettings& stored, const ConnectionSettings& settings);

private:
    void updateEnabled();

    QComboBox* m_direction = nullptr;
    QComboBox* m_polarity = nullptr;
    QSpinBox* m_delay = nullptr;
    QCheckBox* m_lowLatency = nullptr;
};

} // namespace opentop
