#pragma once

#include "model/bus/DriveStatus.h"
#include "model/profile/Profile.h"
#include "model/session/Freshness.h"

#include <QDateTime>
#include <QHash>
#include <QObject>
#include <QTimer>
#include <QVector>
#include <functional>

namespace opentop {

class BusDrives;
class DeviceSession;

// Polls every identified drive of a BusDrives for the few values the bus list shows, one drive
// after the other, at Poll priority so that everything a user asks for goes first. A cycle
// starts only when the previous one is complete; the interval is measured start to start.
// Families without some roles get what applies (the DC controller: running from PWM, no
// alarm, no priority setting).
class DriveStatusPoller : public QObject
{
    Q_OBJECT
public:
    explicit DriveStatusPoller(BusDrives* drives, QObject* parent = nullptr);
    ~DriveStatusPoller() override;

    BusDrives* drives() const { return m_drives; }
    void setInterval(int ms) { m_intervalMs = ms; }
    int interval() const { return m_intervalMs; }

    void start();
    void stop();
    bool isActive() const { return m_active; }
    // Polls at once (a new cycle starts when the one under way completes).
    void pollNow();
    // Calls `then` once a cycle that started after this call has completed, so that what the
    // status says is newer than something just done (a motor just stopped); at once when not
    // polling, and after `limitMs` at the latest.
    void afterFreshCycle(QObject* context, std::function<void()> then, int limitMs = 3000);

    // The status of `slave`; a default (grey, not polled) one for drives not polled yet.
    DriveStatus status(int slave) const { return m_status.value(slave); }
    // Whether what the status says of `slave` is live (monitor/Freshness): answered within a
    // few poll intervals while the link is up and no scan holds the bus (polling waits then).
    Freshness::State freshness(int slave, const QDateTime& now) const;
    // The light to show now: the status's colour while live, grey otherwise (never green for
    // a drive that is not answering or a link that is down).
    DriveStatus::Led shownLed(int slave, const QDateTime& now) const;
    // Parameters polled for `slave` (empty for drives without a session).
    QStringList parametersFor(int slave) const;
    int cyclesCompleted() const { return m_cycles; }
    // The DBU's LED rules applied to a status (public for tests and other views).
    static DriveStatus::Led ledFor(const DriveStatus& status);
    // ledFor and the entry of `profile`'s status LED table for it (nullptr: none).
    static void applyLed(DriveStatus* status, const Profile* profile);

signals:
    void statusChanged(int slave);
    void cycleFinished();

private:
    void startCycle();
    void pollNext();
    void pollDrive(int slave);
    void readAlarm(int slave, quint64 generation);
    void driveDone(int slave, const DriveStatus& status);
    void scheduleNext();
    void skipIfGone(int slave);

    BusDrives* m_drives;
    int m_intervalMs = 1000;
    bool m_active = false;
    bool m_busy = false;
    bool m_pollAgain = false;
    quint64 m_generation = 0; // results of an earlier start() are dropped
    QVector<int> m_queue;     // drives still to poll this cycle
    int m_current = 0;        // the drive being polled
    DeviceSession* m_currentSession = nullptr;
    QHash<int, DriveStatus> m_status;
    QTimer m_timer;
    qint64 m_cycleStartMs = 0;
    int m_cycles = 0;
};

} // namespace opentop
