#pragma once

#include "model/monitor/DeviceMonitor.h"

#include <QDateTime>
#include <QGroupBox>
#include <QPointer>
#include <QTimer>
#include <QVector>

class QLabel;

namespace opentop {

class MonitorHub;

// What a drive is doing now, on its Test run page: speed, target, load (or a DC controller's
// output duty), the running state with its direction, the alarm state and the running data it
// runs, from the hub's
// samples, each with its age. The drive is watched (polled) while this box is visible, so a run
// started from the page is also in the drive's trend. An old value or a lost link shows grey
// with the time of the last answer (Freshness), never as live.
class RunLiveState : public QGroupBox
{
    Q_OBJECT
public:
    RunLiveState(MonitorHub* hub, int slave, QWidget* parent = nullptr);
    ~RunLiveState() override;

    // A row's value as shown ("1350 r/min", "Running CW", "none"); empty when never read.
    QString valueText(const QString& row) const;
    QString speedText() const { return valueText(m_speedRow); }
    QString stateText() const { return valueText(QStringLiteral("state")); }
    // The running data the drive reports it runs ("SPno4"), live like the other rows.
    QString runningDataText() const { return valueText(QStringLiteral("spno")); }
    QString alarmText() const { return valueText(QStringLiteral("alarm")); }
    // The age column of a row: "0.3 s old" or "last answer 10:31:05 (12 s old)".
    QString ageText(const QString& row) const;
    bool isStale() const { return m_stale; }
    QDateTime lastAnswer() const { return m_last; }

public slots:
    // Ages and staleness against the clock (also on a timer while shown).
    void updateAges();

signals:
    void updated();

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    struct Row
    {
        QString key; // parameter name, or "state" / "alarm"
        QLabel* value = nullptr;
        QLabel* age = nullptr;
    };
    void addRow(const QString& key, const QString& label);
    void showSample(const MonitorSample& sample);
    const Row* row(const QString& key) const;

    QPointer<MonitorHub> m_hub;
    int m_slave;
    QVector<Row> m_rows;
    QString m_speedRow;
    QString m_dutyRow; // a running state told by a number (output duty)
    QDateTime m_last;
    bool m_stale = false;
    bool m_watching = false;
    QTimer m_timer;
};

} // namespace opentop
