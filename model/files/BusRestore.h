#pragma once

#include "model/files/BackupDevice.h"
#include "model/files/RestorePlan.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>
#include <functional>

namespace opentop {

class DeviceSession;
class Restorer;

// A restore of several drives from one backup: every drive is checked against the file first
// (a refusal of any writes nothing at all), then each is restored in turn (Restorer: only what
// differs, in dependency order, read back). After a lost bus or a cancel the drives not reached
// are reported as "not attempted", never silently left out. The one home of this workflow:
// `opentop-cli restore` and the window's restore dialog only choose, ask and show.
class BusRestore : public QObject
{
    Q_OBJECT
public:
    struct Job
    {
        int slave = 0;       // the machine number written to on the bus
        BackupDevice device; // the file's drive restored onto it
    };
    using Sessions = std::function<DeviceSession*(int slave)>;
    using Done = std::function<void(const QVector<RestorePlan>&)>;

    explicit BusRestore(Sessions sessions, QObject* parent = nullptr);

    // The refusals, one plan each (empty: every drive takes its part of the file). A drive
    // without a session is refused too.
    QVector<RestorePlan> check(const QVector<Job>& jobs) const;
    // One plan per job, in the jobs' order; `done` runs once, never before start() returns.
    // A preview (`dryRun`) reads and plans; nothing is written.
    void start(const QVector<Job>& jobs, bool dryRun, Done done);
    // Stops after the write in progress has been read back; the rest are not attempted.
    void cancel();
    bool isRunning() const { return bool(m_done); }

    // The most serious outcome of the drives attempted decides the run's (for an exit code):
    // planned < done < refused < mismatch < communication < interrupted; drives not attempted
    // make it interrupted unless the bus was lost.
    static RestorePlan::Outcome worst(const QVector<RestorePlan>& plans);

signals:
    void driveStarted(int slave, int index, int total);
    void progress(int slave, int done, int total, const QString& parameter);
    void driveFinished(const opentop::RestorePlan& plan);

private:
    void next();

    Sessions m_sessions;
    QVector<Job> m_jobs;
    bool m_dryRun = false;
    int m_next = 0;
    bool m_cancel = false;
    QPointer<Restorer> m_restorer;
    QVector<RestorePlan> m_plans;
    Done m_done;
};

} // namespace opentop
