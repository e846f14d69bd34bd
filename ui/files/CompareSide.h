#pragma once

#include "files/BackupDevice.h"
#include "files/BackupFile.h"

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
// read for the last comparison is kept with it.
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
    // Loads the file; `slave` 0 takes its first drive. False with *error when refused.
    bool loadFile(const QString& path, int slave, QString* error);
    const BackupDevice* fileDevice() const; // the chosen drive of the loaded file, if any
    QString fileName() const;               // of the path typed or browsed

    // The settings resolved for the last comparison, and how the table heads them.
    void setResolved(const BackupDevice& device, const QString& title);
    const BackupDevice& device() const { return m_device; }
    QString title() const { return m_title; }

signals:
    // A file was typed or browsed; the dialog loads it and reports a refusal.
    void fileChosen(const QString& path);

private:
    void updateEnabled();
    void browse(); // modal file dialog

    QComboBox* m_source;
    QComboBox* m_drive;
    QLineEdit* m_path;
    QPushButton* m_browse;
    QComboBox* m_fileDrive;
    std::optional<BackupFile> m_file;
    BackupDevice m_device;
    QString m_title;
};

} // namespace opentop
