#pragma once

#include "model/bus/BusDrives.h"
#include "model/files/BackupFile.h"
#include "model/files/BusRestore.h"
#include "model/files/RestorePlan.h"
#include "ui/files/RestoreChoice.h"
#include "ui/files/RestorePlanTable.h"

#include <QDialog>
#include <QPointer>
#include <optional>

class QCheckBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace opentop {

// Restores drives from a backup file: choose the file, which of its drives goes to which drive
// on the bus (the same machine number unless changed) and which settings; Preview reads the
// drives and shows what would be written; Write (only after a preview, only on the user's
// click) writes, verifies by read-back and reports setting by setting. A refused file or a
// family/variant mismatch is shown with its reason, and then nothing is written to any drive.
class RestoreDialog : public QDialog
{
    Q_OBJECT
public:
    using Column = RestorePlanTable::Column;

    explicit RestoreDialog(BusDrives* drives, QWidget* parent = nullptr);

    bool setPath(const QString& path); // false: refused, errorText() says why
    QString errorText() const { return m_error; }
    QVector<int> fileSlaves() const;
    // 0: do not restore this drive of the file.
    void setTarget(int fileSlave, int busSlave) { m_choice->setTarget(fileSlave, busSlave); }
    int target(int fileSlave) const { return m_choice->target(fileSlave); }
    // The others are left out.
    void setParameters(int fileSlave, const QStringList& names)
    {
        m_choice->setParameters(fileSlave, names);
    }

    void preview(); // dry run; previewFinished() follows
    bool write();   // false when there is no current preview to write
    void cancel();  // after the write in progress has been read back
    bool isBusy() const { return m_restore->isRunning(); }
    bool canWrite() const { return m_previewed && !isBusy(); }

    const QVector<RestorePlan>& plans() const { return m_plans; }
    bool written() const { return m_written; }
    QString outcomeText() const; // the text under the table
    QString cellText(int slave, const QString& parameter, Column column) const
    {
        return m_table->cellText(slave, parameter, column);
    }
    bool isMismatchHighlighted(int slave, const QString& parameter) const
    {
        return m_table->isFailureHighlighted(slave, parameter);
    }
    QCheckBox* differencesOnlyBox() const { return m_table->filterBox(); }
    RestorePlanTable* table() const { return m_table; }
    QString reportText() const;
    bool saveReport(const QString& path, QString* error) const;
    // While writing, closing only cancels: the dialog stays to show what was written.
    void reject() override;

signals:
    void previewFinished();
    void writeFinished();
    void progress(int slave, int done, int total); // after each write of a restore

private:
    using Job = RestoreChoice::Job;

    void chooseFile();                     // modal file dialog, then setPath()
    void confirmAndWrite();                // modal confirmation, then write()
    void chooseReportPath();               // modal file dialog, then saveReport()
    bool refuse(const QVector<Job>& jobs); // true when a drive refuses the file
    void start(bool dryRun);
    void finish(bool dryRun);
    void selectionChanged();
    void showMessage(const QString& text, bool error);
    void updateButtons();

    QPointer<BusDrives> m_drives;
    std::optional<BackupFile> m_file;
    QString m_path;
    QString m_error;
    BusRestore* m_restore; // the workflow; this dialog chooses, asks and shows
    bool m_dryRun = false;
    QVector<RestorePlan> m_plans;
    bool m_previewed = false;
    bool m_written = false;
    QLineEdit* m_pathEdit;
    RestoreChoice* m_choice;
    RestorePlanTable* m_table;
    QProgressBar* m_progress;
    QLabel* m_message;
    QPushButton* m_previewButton;
    QPushButton* m_writeButton;
    QPushButton* m_cancelButton;
    QPushButton* m_saveButton;
};

} // namespace opentop
