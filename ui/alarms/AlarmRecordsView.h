#pragma once

#include "model/alarms/AlarmHistory.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace opentop {

class DeviceSession;

// What one read of a drive's alarm records shows on its Alarms page: the alarm and warning
// tables (newest first, each under its label), the cause and remedy of the record selected in
// either, and the communication error register decoded. It only shows a report: the page reads
// the drive and sends the commands.
class AlarmRecordsView : public QWidget
{
    Q_OBJECT
public:
    explicit AlarmRecordsView(DeviceSession* session, QWidget* parent = nullptr);

    // Shows `report` (kept: the selected record's detail is looked up in it).
    void showReport(const AlarmHistory::Report& report);
    const AlarmHistory::Report& report() const { return m_report; }

    // 0: the alarm table, 1: the warning table.
    QTableWidget* table(int which) const { return m_tables[which]; }
    QString detailText() const;
    QString commErrorText() const;

    // Where each table's history is in a report (0: "alarm", 1: "warning"); null when absent.
    static const AlarmHistory::History* historyOf(const AlarmHistory::Report& report, int which);
    // "07h"; "Alarm-Reset", "power cycle", "by itself" for a code table's reset kind.
    static QString codeText(qint64 code);
    static QString clearedByText(const QString& reset);

private:
    void showCommError(const AlarmHistory::Report& report);
    void fillTable(int which, const AlarmHistory::History* history);
    void showDetail(int which);

    DeviceSession* m_session;
    AlarmHistory::Report m_report;
    QLabel* m_tableLabels[2];
    QTableWidget* m_tables[2];
    QLabel* m_detail;
    QLabel* m_commError;
};

} // namespace opentop
