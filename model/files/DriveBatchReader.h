#pragma once

#include "model/files/BackupReader.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>
#include <functional>

namespace opentop {

class DeviceSession;

// Reads several drives' settings one after the other (BackupReader each): the one home of
// "read these drives" for a backup, a compare and a recipe from a golden unit. A drive that is
// not on the bus, or whose preparation (proving its variant) fails, is reported with why; a
// cancel stops after the drive being read and the rest are reported as not read, never left
// out; with `stopAtFailure` the first failure ends the run the same way.
class DriveBatchReader : public QObject
{
    Q_OBJECT
public:
    struct Drive
    {
        int slave = 0;
        bool attempted = false; // false: cancelled or stopped before this drive
        QString error;          // not on the bus, or its preparation failed
        BackupReader::Result read;
        bool ok() const { return attempted && error.isEmpty() && read.ok; }
        // What went wrong, one line each, for people ("drive 1 (DBU200-D): cannot read …").
        QStringList problems() const;
    };
    using Sessions = std::function<DeviceSession*(int slave, QString* error)>;
    // Runs before a drive is read; `go` with an empty error reads it, with an error skips it.
    using Prepare =
        std::function<void(DeviceSession* session, std::function<void(const QString&)> go)>;
    struct Options
    {
        bool stopAtFailure = false;
        Prepare prepare;
    };
    using Done = std::function<void(const QVector<Drive>&)>;

    explicit DriveBatchReader(Sessions sessions, QObject* parent = nullptr);

    // One entry per slave, in order; `done` runs once, never before start() returns.
    void start(const QVector<int>& slaves, const Options& options, Done done);
    void cancel();
    bool isRunning() const { return bool(m_done); }

signals:
    void driveStarted(int slave, int index, int total);
    void driveFinished(const opentop::DriveBatchReader::Drive& drive);

private:
    void next();
    void finishDrive(const Drive& drive);

    Sessions m_sessions;
    Options m_options;
    QVector<int> m_slaves;
    QVector<Drive> m_drives;
    bool m_cancel = false;
    QPointer<BackupReader> m_reader;
    Done m_done;
};

} // namespace opentop
