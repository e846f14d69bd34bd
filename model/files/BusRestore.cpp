#include "model/files/BusRestore.h"

#include "model/files/Restorer.h"
#include "model/session/DeviceSession.h"

#include <QTimer>

namespace opentop {

BusRestore::BusRestore(Sessions sessions, QObject* parent)
    : QObject(parent)
    , m_sessions(std::move(sessions))
{
}

QVector<RestorePlan> BusRestore::check(const QVector<Job>& jobs) const
{
    QVector<RestorePlan> refusals;
    for (const Job& job : jobs) {
        DeviceSession* session = m_sessions(job.slave);
        RestorePlan plan;
        if (!session) {
            plan.slave = job.slave;
            plan.title = job.device.title();
            plan.outcome = RestorePlan::Outcome::Refused;
            plan.reason = tr("machine number %1 is not a drive on the bus").arg(job.slave);
        } else {
            plan = RestorePlan::check(session->profile(), session->variant(), job.device);
            plan.machineName = session->machineName();
            plan.slave = job.slave;
        }
        if (plan.refused())
            refusals << plan;
    }
    return refusals;
}

RestorePlan::Outcome BusRestore::worst(const QVector<RestorePlan>& plans)
{
    using Outcome = RestorePlan::Outcome;
    static const QVector<Outcome> severity{Outcome::Planned,       Outcome::Done,
                                           Outcome::Refused,       Outcome::Mismatch,
                                           Outcome::Communication, Outcome::Interrupted};
    Outcome result = Outcome::Planned;
    bool skipped = false;
    for (const RestorePlan& p : plans) {
        skipped = skipped || !p.attempted;
        if (p.attempted && severity.indexOf(p.outcome) > severity.indexOf(result))
            result = p.outcome;
    }
    // Drives left out by a cancel make the run a cancelled one, though the drives attempted
    // all finished; after a lost bus the failure already says why.
    if (skipped && result != Outcome::Communication)
        result = Outcome::Interrupted;
    return result;
}

void BusRestore::start(const QVector<Job>& jobs, bool dryRun, Done done)
{
    m_jobs = jobs;
    m_dryRun = dryRun;
    m_next = 0;
    m_cancel = false;
    m_plans.clear();
    m_done = std::move(done);
    QTimer::singleShot(0, this, &BusRestore::next);
}

void BusRestore::cancel()
{
    m_cancel = true;
    if (m_restorer)
        m_restorer->cancel();
}

void BusRestore::next()
{
    if (m_next >= m_jobs.size()) {
        auto done = std::move(m_done);
        m_done = nullptr;
        if (done)
            done(m_plans);
        return;
    }
    const Job& job = m_jobs.at(m_next++);
    const bool stopped =
        !m_plans.isEmpty() && (m_plans.last().outcome == RestorePlan::Outcome::Communication ||
                               m_plans.last().outcome == RestorePlan::Outcome::Interrupted);
    DeviceSession* session = m_sessions(job.slave);
    if (stopped || m_cancel || !session) {
        // The bus failed or the user stopped: later drives are left alone, and said so.
        RestorePlan skipped;
        skipped.slave = job.slave;
        skipped.title = job.device.title();
        skipped.outcome = RestorePlan::Outcome::Interrupted;
        skipped.attempted = false;
        skipped.reason = tr("not attempted");
        m_plans << skipped;
        emit driveFinished(skipped);
        QTimer::singleShot(0, this, &BusRestore::next);
        return;
    }
    emit driveStarted(job.slave, m_next - 1, int(m_jobs.size()));
    m_restorer = new Restorer(session, this);
    connect(m_restorer, &Restorer::progress, this,
            [this, slave = job.slave](int done, int total, const QString& parameter) {
                emit progress(slave, done, total, parameter);
            });
    Restorer::Options options;
    options.dryRun = m_dryRun;
    m_restorer->start(job.device, options, [this](const RestorePlan& plan) {
        m_restorer->deleteLater();
        m_plans << plan;
        emit driveFinished(plan);
        next();
    });
}

} // namespace opentop
