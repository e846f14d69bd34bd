#pragma once

#include "alarms/AlarmHistory.h"

#include <QLabel>
#include <QPointer>
#include <QWidget>

class QPushButton;
class QTableWidget;

namespace opentop {

class DeviceSession;

// A drive's alarm and warning histories (newest first) with the cause and remedy of the
// selected record, the communication error register decoded, and the commands Re-read, Reset
// alarm and Clear records. Reset and clear ask for confirmation first; everything runs
// asynchronously through AlarmHistory and ends with operationFinished().
class AlarmsPage : public QWidget
{
    Q_OBJECT
public:
    explicit AlarmsPage(DeviceSession* session, QWidget* parent = nullptr);
    ~AlarmsPage() override;

    DeviceSession* session() const { return m_session; }
    bool isBusy() const { return m_busy; }
    const AlarmHistory::Report& report() const { return m_report; }

    // Reads the records and the error register again.
    void refresh();
    // Ask for confirmation (a modal QMessageBox), then send the command.
    void resetAlarm();
    void clearRecords();

    QTableWidget* alarmTable() const { return m_tables[0]; }
    QTableWidget* warningTable() const { return m_tables[1]; }
    // Cause and remedy of the selected record; the communication error register decoded; the
    // last command's result and what the drive says.
    QString detailText() const { return m_detail->text(); }
    QString commErrorText() const { return m_commError->text(); }
    QString statusText() const { return m_status->text(); }

    // "07h"; "Alarm-Reset", "power cycle", "by itself" for a code table's reset kind.
    static QString codeText(qint64 code);
    static QString clearedByText(const QString& reset);

signals:
    void operationFinished();

private:
    void setBusy(bool busy, const QString& status = QString());
    void showReport(const AlarmHistory::Report& report);
    void fillTable(int which, const AlarmHistory::History* history);
    void showDetail(int which);
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
    AlarmHistory::Report m_report;
    QString m_commandResult;
    bool m_busy = false;
    QLabel* m_title;
    QLabel* m_status;
    QLabel* m_tableLabels[2];
    QTableWidget* m_tables[2];
    QLabel* m_detail;
    QLabel* m_commError;
    QPushButton* m_reread;
    QPushButton* m_reset;
    QPushButton* m_clear;
};

} // namespace opentop
