#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;

namespace opentop {

class MonitorHub;
class StaleLook;

// The line above a drive's live values: how often the drives are polled, pause and resume,
// and the values' age with the sample rate, or why they are not live (polling paused,
// connection lost, the drive does not answer).
class MonitorPollBar : public QWidget
{
    Q_OBJECT
public:
    MonitorPollBar(MonitorHub* hub, int slave, QWidget* parent = nullptr);

    // Shows what `look` tells of the drive's values; `lastError`: why the last read failed
    // (empty once a sample came).
    void showFreshness(const StaleLook& look, const QString& lastError);
    // The status shown: the values' age and the sample rate, or why they are not live.
    QString text() const;

private:
    MonitorHub* m_hub;
    int m_slave;
    QComboBox* m_rate;
    QPushButton* m_pause;
    QLabel* m_status;
};

} // namespace opentop
