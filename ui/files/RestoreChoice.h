#pragma once

#include "model/files/BackupFile.h"

#include <QTreeWidget>

namespace opentop {

class BusDrives;

// What a restore is to do, as the user chooses it: one checkable entry per drive of the file
// with its settings beneath (all ticked at first), and per drive the bus drive it goes to (the
// one with the file's machine number at first, as the command line does).
class RestoreChoice : public QTreeWidget
{
    Q_OBJECT
public:
    struct Job
    {
        int busSlave = 0;
        BackupDevice device; // the chosen settings only
    };

    explicit RestoreChoice(QWidget* parent = nullptr);

    void setFile(const BackupFile& file, BusDrives* drives); // ticks everything
    void setTarget(int fileSlave, int busSlave);             // 0: do not restore it
    int target(int fileSlave) const;
    void setParameters(int fileSlave, const QStringList& names);
    // The chosen drives; empty with *error when nothing is chosen or a target is missing.
    QVector<Job> jobs(const BackupFile& file, BusDrives* drives, QString* error) const;

signals:
    void changed();

private:
    QTreeWidgetItem* driveItem(int fileSlave) const;
};

} // namespace opentop
