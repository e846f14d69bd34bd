#pragma once

#include "model/files/BackupDevice.h"
#include "model/files/BackupFile.h"

#include <QGroupBox>
#include <QPointer>
#include <optional>

class QComboBox;
class QLineEdit;
class QPushButton;

namespace opentop {

class BusDrives;

// One side of a comparison as the user picks it: a drive on the bus, a drive in a backup file
// (refused files never get here), or, on side B only, the profile's factory defaults. What was
// read for the last comparison is kept with it. A file's drive follows the other side's drive
// until the user picks one.
class CompareSide : public QGroupBox
{
    Q_OBJECT
public:
    enum Source
    {
        BusDrive,
        FileDrive,
        Defaults // side B only
    };

    CompareSide(const QString& title, bool offerDefaults, BusDrives* drives,
                QWidget* parent = nullptr);

    Source source() const;
    int busSlave() const; // the chosen drive on the bus; 0 when there is none
    void chooseBusDrive(int slave);
    void chooseDefaults();
    // Loads the file; `slave` 0 takes the drive that goes with the other side's (follow()),
    // else its first. False with *error when refused.
    bool loadFile(const QString& path, int slave, QString* error);
    // The other side now shows drive `slave` of `family`: the drive in this side's file follows
    // it (the same machine number, else the same family) until the user picks one.
    void follow(int slave, const QString& family);
    // The drive this side shows: machine number and family (0 and empty when none).
    int shownSlave() const;
    QString shownFamily() const;
    const BackupDevice* fileDevice() const; // the chosen drive of the loaded file, if any
    QString fileName() const;               // of the path typed or browsed

    // The settings resolved for the last comparison, and how the table heads them.
    void setResolved(const BackupDevice& device, const QString& title);
    const BackupDevice& device() const { return m_device; }
    QString title() const { return m_title; }

signals:
    // A file was typed or browsed; the dialog loads it and reports a refusal.
    void fileChosen(const QString& path);
    // Another drive is shown (chosen on the bus or in the file, or another source).
    void driveChanged();

private:
    void updateEnabled();
    void browse(); // modal file dialog

    QComboBox* m_source;
    QComboBox* m_drive;
    QLineEdit* m_path;
    QPushButton* m_browse;
    QComboBox* m_fileDrive;
    std::optional<BackupFile> m_file;
    BusDrives* m_drives;
    int m_otherSlave = 0; // the other side's drive, which the file's drive follows
    QString m_otherFamily;
    bool m_filePicked = false; // the user chose the drive in the file
    BackupDevice m_device;
    QString m_title;
};

} // namespace opentop
