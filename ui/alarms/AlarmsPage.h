#pragma once

#include "model/alarms/AlarmHistory.h"
#include "ui/alarms/AlarmRecordsView.h"

#include <QLabel>
#include <QPointer>
#include <QWidget>
#include <optional>

class QPushButton;
class QTableWidget;

namespace opentop {

class AlarmFollower;
class DeviceSession;
class DriveStatusPoller;
class MonitorHub;
class StaleLook;

// A drive's Alarms page: its alarm and warning records as an AlarmRecordsView shows them, the
// alarm state followed live, and the commands Re-read, Reset alarm and Clear records. Reset and
// clear ask for confirmation first; everything runs asynchronously through AlarmHistory and
// ends with operationFinished().
class AlarmsPage : public QWidget
{
    Q_OBJECT
public:
    explicit AlarmsPage(DeviceSession* session, QWidget* parent = nullptr);
    ~AlarmsPage() override;

    DeviceSession* session() const { return m_session; }
    bool isBusy() const { return m_busy; }
    const AlarmHistory::Report& report() const { return m_records->report(); }

    // Follows the drive live: watches it through `hub` while the page is shown and reads the
    // records again when the drive's alarm state changes (raised, cleared, another code, a
    // power cycle seen) as the hub's samples or the poller's status (the banner's source)
    // report it, so that the page never contradicts the banner.
    void followLive(MonitorHub* hub, DriveStatusPoller* poller);
    // Reads the records and the error register again.
    void refresh();
    // The alarm state the page shows: whether an alarm is active and the newest record's code.
    std::optional<bool> shownAlarmActive() const { return report().alarmActive; }
    std::optional<qint64> shownAlarmCode() const;
    // "Alarm state updated 0.4 s ago" / "last answer ..." below the status.
    QString ageText() const;
    int autoRefreshes() const;
    // Ask for confirmation (a modal QMessageBox), then send the command.
    void resetAlarm();
    void clearRecords();

    QTableWidget* alarmTable() const { return m_records->table(0); }
    QTableWidget* warningTable() const { return m_records->table(1); }
    // Cause and remedy of the selected record; the communication error register decoded; the
    // last command's result and what the drive says.
    QString detailText() const { return m_records->detailText(); }
    QString commErrorText() const { return m_records->commErrorText(); }
    QString statusText() const { return m_status->text(); }

signals:
    void operationFinished();

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    // Whether a drive's alarm state differs from what the page shows.
    bool contradicts(std::optional<bool> active, std::optional<qint64> code) const;
    void setBusy(bool busy, const QString& status = QString());
    void startReset();
    void startClear();
    void finish(const QString& status);
    void confirm(const QString& title, const QString& text, const QString& details,
                 const QString& action, void (AlarmsPage::*then)());
    // Wraps a callback so that it is dropped, and the history deleted, once the page is gone.
    template <typename T>
    std::function<void(const T&)> guarded(void (AlarmsPage::*handler)(const T&));
    void readDone(const AlarmHistory::Report& report);
    void resetDone(const AlarmHistory::ResetOutcome& outcome);
    void clearDone(const AlarmHistory::ClearOutcome& outcome);

    DeviceSession* m_session;
    QPointer<AlarmHistory> m_history;
    QString m_commandResult;
    bool m_busy = false;
    QLabel* m_title;
    QLabel* m_status;
    AlarmRecordsView* m_records;
    QPushButton* m_reread;
    QPushButton* m_reset;
    QPushButton* m_clear;
    QLabel* m_age;
    AlarmFollower* m_follower = nullptr;
    StaleLook* m_look = nullptr;
};

} // namespace opentop
