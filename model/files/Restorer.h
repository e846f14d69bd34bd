#pragma once

#include "model/files/BackupDevice.h"
#include "model/files/RestorePlan.h"

#include <QObject>
#include <functional>

namespace opentop {

class DeviceSession;

// Brings one drive back to the settings of a backup: checks the whole file against the drive
// before anything is written, writes only what differs in dependency order, verifies every
// write by reading it back, stores what the drive would otherwise lose at power-off, and
// reports parameter by parameter. Asynchronous; cancel() stops once the write in progress has
// been read back (a write and its verification belong together), before the next one. Running
// it again after an interruption or failure completes the restore. A drive's communication
// group children execute the writes too: they check every value first, and are read back.
class Restorer : public QObject
{
    Q_OBJECT
public:
    struct Options
    {
        bool dryRun = false; // read the drive and plan; write nothing
    };
    using Done = std::function<void(const RestorePlan&)>;

    explicit Restorer(DeviceSession* session, QObject* parent = nullptr);

    // `done` runs once, on this object's thread, never before start() returns.
    void start(const BackupDevice& file, const Options& options, Done done);
    void cancel();
    bool isRunning() const { return m_running; }

signals:
    // After each write (or store command) has finished.
    void progress(int done, int total, const QString& parameter);

private:
    void readDrive();
    // The drives that execute the writes too (a group's children) must allow every value to be
    // written: otherwise the restore is refused before anything is sent.
    void checkReached(std::function<void()> then);
    void writeNext();
    void readBack();
    void stopRemaining(RestorePlan::Outcome outcome, const QString& reason);
    void finish(RestorePlan::Outcome outcome);

    DeviceSession* m_session;
    BackupDevice m_file;
    Options m_options;
    Done m_done;
    RestorePlan m_plan;
    int m_finished = 0;
    bool m_cancel = false;
    bool m_running = false;
};

} // namespace opentop
