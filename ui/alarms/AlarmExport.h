#pragma once

#include "model/alarms/AlarmHistory.h"

#include <QObject>
#include <QVector>

namespace opentop {

class BusDrives;

// Exports the alarm and warning histories of every drive of a BusDrives to a CSV file: one row
// per record (machine number, model, kind, record #, code, panel code, name, cleared by, cause,
// remedy). Reads the drives one after the other, asynchronously, then writes the file at once
// through QSaveFile; finished() tells the outcome.
class AlarmExport : public QObject
{
    Q_OBJECT
public:
    struct DriveReport
    {
        int slave = 0;
        QString model;
        QString name; // the user's name for the machine
        AlarmHistory::Report report;
    };

    explicit AlarmExport(BusDrives* drives, QObject* parent = nullptr);

    bool isBusy() const { return m_busy; }
    // Starts reading; false (and no finished()) when an export is already under way.
    bool exportTo(const QString& path);
    // The reports read by the last export, in machine number order.
    const QVector<DriveReport>& reports() const { return m_reports; }

    // The CSV text (RFC 4180, CRLF line ends, a header row) for the given reports.
    static QString csv(const QVector<DriveReport>& reports);

signals:
    // `message` says what was written, and which drives could not be read.
    void finished(bool ok, const QString& message);

private:
    void readNext();
    void writeFile();

    BusDrives* m_drives;
    bool m_busy = false;
    QString m_path;
    QVector<int> m_queue;
    QVector<DriveReport> m_reports;
    QStringList m_errors;
};

} // namespace opentop
