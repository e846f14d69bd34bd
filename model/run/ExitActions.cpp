#include "model/run/ExitActions.h"

#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/RoleEvaluator.h"
#include "model/run/StopAll.h"
#include "model/session/DeviceSession.h"

#include <QPointer>

namespace opentop {

namespace {
const QString kIoPriority = QStringLiteral("ioPriority");
}

ExitActions::ExitActions(BusDrives* drives, QObject* parent)
    : QObject(parent)
    , m_drives(drives)
{
}

void ExitActions::leave(const ExitPlan& plan, ExitPlan::Choice choice, Done done)
{
    switch (choice) {
    case ExitPlan::Choice::Leave:
        done({});
        return;
    case ExitPlan::Choice::GiveBackOnly:
        returnToIoPriority(plan.returnable(), std::move(done));
        return;
    case ExitPlan::Choice::StopAndGiveBack:
        break;
    }
    const QVector<int> running = plan.running();
    const QVector<int> returnable = plan.returnable();
    if (running.isEmpty()) {
        returnToIoPriority(returnable, std::move(done));
        return;
    }
    QPointer<ExitActions> self(this);
    stop(running, [self, running, returnable, done](const QStringList& failures,
                                                    const QVector<int>& stopped) {
        QStringList all = failures;
        QVector<int> giveBack;
        for (int slave : returnable) {
            if (!running.contains(slave) || stopped.contains(slave))
                giveBack << slave;
            else
                all << tr("Machine number %1: left in communication priority, as it was not "
                          "confirmed stopped")
                           .arg(slave);
        }
        if (!self) {
            done(all);
            return;
        }
        self->returnNext(giveBack, all, done);
    });
}

void ExitActions::stop(const QVector<int>& slaves,
                       std::function<void(const QStringList&, const QVector<int>&)> done)
{
    auto* stop = new StopAll(m_drives->client(), ProfileRegistry::builtIn(), this);
    BusDrives* drives = m_drives;
    stop->setSessionLookup([drives](int slave) { return drives->session(slave); });
    stop->run(slaves, [stop, done](const StopReport& report) {
        stop->deleteLater();
        QStringList failures;
        QVector<int> stopped;
        for (const StopBroadcast& b : report.broadcasts) {
            if (!b.sent)
                failures
                    << tr("The stop broadcast to the %1 drives failed: %2").arg(b.family, b.error);
        }
        for (const StopResult& r : report.drives) {
            if (r.state == StopResult::State::Stopped)
                stopped << r.slave;
            else if (r.state == StopResult::State::StillRunning)
                failures << tr("Machine number %1: STILL RUNNING (%2) %3")
                                .arg(r.slave)
                                .arg(r.speedText, r.detail)
                                .trimmed();
            else
                failures << tr("Machine number %1: NO ANSWER, not confirmed stopped %2")
                                .arg(r.slave)
                                .arg(r.detail)
                                .trimmed();
        }
        done(failures, stopped);
    });
}

void ExitActions::returnToIoPriority(const QVector<int>& slaves, Done done)
{
    returnNext(slaves, {}, std::move(done));
}

void ExitActions::returnNext(QVector<int> slaves, QStringList failures, Done done)
{
    if (slaves.isEmpty()) {
        done(failures);
        return;
    }
    const int slave = slaves.takeFirst();
    DeviceSession* session = m_drives->session(slave);
    const ProfileRole* role = session ? session->profile().role(kIoPriority) : nullptr;
    const ParameterMeta* meta = role ? session->profile().parameter(role->parameter) : nullptr;
    if (!meta || !role->value) {
        failures << tr("Machine number %1: no way to give control back to its inputs is known")
                        .arg(slave);
        returnNext(slaves, failures, done);
        return;
    }
    DeviceSession::WriteOptions options;
    options.explicitCommand = true; // the user chose this in the exit question
    QPointer<ExitActions> self(this);
    session->write(meta->name, RoleEvaluator::writeText(*meta, *role->value, session->context()),
                   options,
                   [self, slave, slaves, failures, done](const DeviceSession::Outcome& o) mutable {
                       if (!o.ok)
                           failures << tr("Machine number %1: %2").arg(slave).arg(o.error);
                       if (self)
                           self->returnNext(slaves, failures, done);
                       else
                           done(failures);
                   });
}

} // namespace opentop
