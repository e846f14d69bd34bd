#include "model/files/Restorer.h"

#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "model/session/ReachedDrives.h"
#include "model/session/StoreTracker.h"

#include <algorithm>

#include <QPointer>
#include <QTimer>

namespace opentop {

using Item = RestorePlan::Item;

Restorer::Restorer(DeviceSession* session, QObject* parent)
    : QObject(parent)
    , m_session(session)
{
}

void Restorer::cancel()
{
    m_cancel = true;
}

void Restorer::start(const BackupDevice& file, const Options& options, Done done)
{
    m_file = file;
    m_options = options;
    m_done = std::move(done);
    m_cancel = false;
    m_running = true;
    m_finished = 0;
    // Everything that can refuse the file is decided here, before a single frame is sent.
    m_plan = RestorePlan::check(m_session->profile(), m_session->variant(), file);
    m_plan.slave = m_session->slave();
    m_plan.machineName = m_session->machineName();
    QTimer::singleShot(0, this, [this] {
        if (m_plan.refused())
            finish(RestorePlan::Outcome::Refused);
        else
            readDrive();
    });
}

void Restorer::readDrive()
{
    if (m_cancel) {
        stopRemaining(RestorePlan::Outcome::Interrupted, tr("interrupted before anything was "
                                                            "written"));
        return;
    }
    QPointer<Restorer> self(this);
    m_session->readMany(m_file.parameterNames(), [self](const DeviceSession::ReadManyOutcome& r) {
        if (!self)
            return;
        if (r.failed > 0) {
            QStringList failures;
            for (const QString& name : r.order) {
                if (!r.results.value(name).ok)
                    failures << QStringLiteral("%1: %2").arg(name, r.results.value(name).error);
            }
            self->stopRemaining(RestorePlan::Outcome::Communication,
                                tr("reading the drive failed, nothing written (%1)")
                                    .arg(failures.join(QStringLiteral("; "))));
            return;
        }
        QHash<QString, QVector<quint16>> live;
        for (const QString& name : r.order)
            live.insert(name, self->m_session->cachedRegisters(name));
        self->m_plan.build(self->m_session->profile(), self->m_session->variant(), live,
                           StoreTracker::of(self->m_session)->unstored());
        self->checkReached([self] {
            if (self && self->m_options.dryRun)
                self->finish(RestorePlan::Outcome::Planned);
            else if (self)
                self->writeNext();
        });
    });
}

void Restorer::checkReached(std::function<void()> then)
{
    const ReachedDrives reached(m_session, m_session->reachedDrives());
    QVector<const ParameterMeta*> metas;
    QStringList names;
    for (const Item& item : std::as_const(m_plan.items)) {
        const ParameterMeta* meta = m_session->profile().parameter(item.parameter);
        if (item.action == Item::Action::Write && meta) {
            metas << meta;
            names << item.parameter;
        }
    }
    if (reached.isEmpty() || metas.isEmpty()) {
        then();
        return;
    }
    QPointer<Restorer> self(this);
    reached.ensureKnown(metas, names, [self, reached, names, then](const QString& problem) {
        if (!self)
            return;
        RestorePlan& plan = self->m_plan;
        if (!problem.isEmpty())
            plan.problems << problem;
        for (const Item& item : std::as_const(plan.items)) {
            const ParameterMeta* meta = self->m_session->profile().parameter(item.parameter);
            if (problem.isEmpty() && item.action == Item::Action::Write && meta) {
                const QString refused = reached.problem(*meta, item.fileRegisters, names, true);
                if (!refused.isEmpty())
                    plan.problems << refused;
            }
        }
        if (plan.problems.isEmpty()) {
            then();
            return;
        }
        plan.reason = tr("%n value(s) of the file may not be written to the drives of the "
                         "communication group; nothing written",
                         "", int(plan.problems.size()));
        self->finish(RestorePlan::Outcome::Refused);
    });
}

void Restorer::writeNext()
{
    int index = -1;
    for (int i = 0; i < m_plan.items.size() && index < 0; ++i) {
        if (m_plan.items.at(i).status == Item::Status::Pending)
            index = i;
    }
    if (index < 0) {
        const bool stored =
            std::any_of(m_plan.items.begin(), m_plan.items.end(), [](const Item& i) {
                return i.action == Item::Action::Store && i.status == Item::Status::Verified;
            });
        if (stored)
            readBack();
        else
            finish(RestorePlan::Outcome::Done);
        return;
    }
    if (m_cancel) {
        stopRemaining(
            RestorePlan::Outcome::Interrupted,
            tr("interrupted after %1 of %2 writes; run the restore again to complete it")
                .arg(m_finished)
                .arg(m_plan.count(Item::Action::Write) + m_plan.count(Item::Action::Store)));
        return;
    }
    const Item& item = m_plan.items.at(index);
    DeviceSession::WriteOptions options;
    // Storing is part of what the user asked for when asking for a restore.
    options.explicitCommand = item.action == Item::Action::Store;
    for (int later = index + 1; later < m_plan.items.size(); ++later) {
        if (m_plan.items.at(later).action == Item::Action::Write)
            options.companions << m_plan.items.at(later).parameter;
    }
    QPointer<Restorer> self(this);
    m_session->write(
        item.parameter, item.writeText, options, [self, index](const DeviceSession::Outcome& o) {
            if (!self)
                return;
            Item& done = self->m_plan.items[index];
            ++self->m_finished;
            const int total =
                self->m_plan.count(Item::Action::Write) + self->m_plan.count(Item::Action::Store);
            if (o.ok) {
                done.status = Item::Status::Verified;
                done.error = o.notVerified; // held here, not read back from every drive reached
            } else {
                done.status = o.unconfirmed ? Item::Status::NotConfirmed : Item::Status::Failed;
                done.error = o.error;
                // Read back, but different: the line works, go on with the rest.
                done.mismatch = o.sent && o.value.valid;
            }
            emit self->progress(self->m_finished, total, done.parameter);
            if (!o.ok && !done.mismatch) {
                self->stopRemaining(
                    RestorePlan::Outcome::Communication,
                    o.unconfirmed
                        ? tr("%1 not confirmed (%2): the drive may or may not hold it; run the "
                             "restore again, it reads the drive back first")
                              .arg(done.parameter, done.error)
                        : QStringLiteral("%1: %2").arg(done.parameter, done.error));
                return;
            }
            self->writeNext();
        });
}

void Restorer::readBack()
{
    // The store commands are write-only: reading the settings again shows that storing kept
    // the values (a reload instead of a store would bring back the old ones).
    QStringList names;
    for (const Item& item : m_plan.items) {
        const ParameterMeta* meta = m_session->profile().parameter(item.parameter);
        if (item.action != Item::Action::Store && meta && !meta->storeWith.isEmpty())
            names << item.parameter;
    }
    QPointer<Restorer> self(this);
    m_session->readMany(names, [self](const DeviceSession::ReadManyOutcome& r) {
        if (!self)
            return;
        RestorePlan& plan = self->m_plan;
        for (Item& item : plan.items) {
            const DeviceSession::Outcome o = r.results.value(item.parameter);
            if (!r.results.contains(item.parameter) || !o.ok || item.status == Item::Status::Failed)
                continue;
            if (o.value.registers != item.fileRegisters) {
                item.status = Item::Status::Failed;
                item.mismatch = true;
                const ParameterMeta& meta = *self->m_session->profile().parameter(item.parameter);
                item.error =
                    tr("after storing, the drive holds %1")
                        .arg(ValueCodec::format(meta, o.value, self->m_session->context()));
            }
        }
        if (r.failed > 0) {
            plan.reason = tr("the settings could not be read back after storing");
            self->finish(RestorePlan::Outcome::Communication);
            return;
        }
        self->finish(RestorePlan::Outcome::Done);
    });
}

void Restorer::stopRemaining(RestorePlan::Outcome outcome, const QString& reason)
{
    for (Item& item : m_plan.items) {
        if (item.status == Item::Status::Pending)
            item.status = Item::Status::NotAttempted;
    }
    m_plan.reason = reason;
    finish(outcome);
}

void Restorer::finish(RestorePlan::Outcome outcome)
{
    const bool mismatch = std::any_of(m_plan.items.begin(), m_plan.items.end(),
                                      [](const Item& i) { return i.mismatch; });
    if (outcome == RestorePlan::Outcome::Done && mismatch)
        outcome = RestorePlan::Outcome::Mismatch;
    m_plan.outcome = outcome;
    QStringList changedLine;
    for (const Item& item : m_plan.items) {
        const ParameterMeta* meta = m_session->profile().parameter(item.parameter);
        if (meta && item.status == Item::Status::Verified &&
            RestorePlan::isCommunicationSetting(m_session->profile(), *meta))
            changedLine << QStringLiteral("%1 = %2").arg(item.parameter, item.fileText);
    }
    if (!changedLine.isEmpty())
        m_plan.notes << tr("communication settings changed (%1): they take effect when the drive "
                           "is next powered on; connect with the new settings after that")
                            .arg(changedLine.join(QStringLiteral(", ")));
    m_running = false;
    const Done done = std::move(m_done);
    m_done = nullptr;
    if (done)
        done(m_plan);
}

} // namespace opentop
