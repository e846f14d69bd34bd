#pragma once

#include "transport/ConnectionSettings.h"

#include <QDialog>
#include <QPointer>
#include <QStringList>
#include <QVector>

#include "model/bus/BusDrives.h"
#include "model/files/BackupDevice.h"
#include "model/files/DriveBatchReader.h"

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace opentop {

// Reads the settings of one or several drives, one after the other, and saves them to a backup
// file. Each drive has its own row with a progress bar and result. Cancel stops after the drive
// being read (a half-read drive would be useless) and names the drives left unread. When a
// drive fails, nothing is saved until the user decides to save the drives that were read.
class BackupDialog : public QDialog
{
    Q_OBJECT
public:
    enum Column
    {
        MachineNumber,
        Model,
        Progress,
        Result,
        ColumnCount
    };

    BackupDialog(BusDrives* drives, const ConnectionSettings& connection,
                 QWidget* parent = nullptr);

    // Reads `slaves` in this order and, if every one was read, saves them to `path`.
    void startBackup(const QVector<int>& slaves, const QString& path);
    void cancel(); // after the drive being read
    bool isRunning() const { return m_running; }
    bool isSaved() const { return m_saved; }
    QString path() const { return m_path; }
    QVector<int> notRead() const; // failed, cancelled or without a session
    QVector<int> readSlaves() const;
    QString message() const; // the summary shown under the table
    QString cellText(int slave, Column column) const;
    // Saves the drives that were read, leaving out the others (the user's decision).
    bool saveReadDrives();
    // While reading, closing only cancels: the dialog stays to say what was not read.
    void reject() override;

signals:
    void readFinished();             // every drive read, failed or skipped
    void backupFinished(bool saved); // after saving, or when the user has to decide

private:
    void driveStarted(int slave);
    void driveFinished(const DriveBatchReader::Drive& drive);
    void finishReading();
    bool save();
    int rowOf(int slave) const;
    void setResult(int slave, const QString& text, bool error);
    void showMessage(const QString& text, bool error);

    QPointer<BusDrives> m_drives;
    ConnectionSettings m_connection;
    QString m_path;
    QVector<BackupDevice> m_read;
    QVector<int> m_failed;
    QStringList m_problems;
    QVector<int> m_slaves;      // in table order
    DriveBatchReader* m_reader; // the workflow; this dialog shows it
    bool m_running = false;
    bool m_saved = false;
    QTableWidget* m_table;
    QProgressBar* m_total;
    QLabel* m_message;
    QPushButton* m_cancelButton;
    QPushButton* m_saveRead;
    QPushButton* m_close;
};

} // namespace opentop
