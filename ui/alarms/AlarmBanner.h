#pragma once

#include <QHash>
#include <QWidget>

class QLabel;
class QPushButton;

namespace opentop {

class DriveStatusPoller;

// A red strip over the workspace while any drive polled by a DriveStatusPoller has an active
// alarm: "Machine 1: AL007 Overload — <remedy>", a Show button (showAlarms) and a dismiss for
// the alarm shown. A dismissed alarm stays hidden while it lasts; a new alarm, or the same one
// raised again after it was cleared, shows the strip again. Hidden when no alarm is active.
class AlarmBanner : public QWidget
{
    Q_OBJECT
public:
    explicit AlarmBanner(DriveStatusPoller* poller, QWidget* parent = nullptr);

    // The drive whose alarm is shown; 0 when none.
    int currentSlave() const { return m_slave; }
    QString text() const;
    // Whether an alarm is to be shown (isVisible() also needs the parent shown).
    bool hasAlarm() const { return m_slave != 0; }

    // Hides the alarm shown until it clears; the next drive's alarm, if any, takes its place.
    void dismiss();
    // Re-evaluates every drive (also done on each status change).
    void refresh();

signals:
    void showAlarms(int slave);

private:
    // What identifies one occurrence of an alarm on a drive, for dismissing it.
    QString alarmKey(int slave) const;

    DriveStatusPoller* m_poller;
    QHash<int, QString> m_dismissed; // slave -> alarm key dismissed
    int m_slave = 0;
    QLabel* m_label;
    QPushButton* m_show;
    QPushButton* m_dismiss;
};

} // namespace opentop
