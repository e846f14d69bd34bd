#include "model/session/ReachedDrives.h"

#include "model/profile/ValueCodec.h"
#include "model/session/BlockReader.h"
#include "model/session/DependentValues.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <memory>

namespace opentop {

ReachedDrives::ReachedDrives(DeviceSession* target, const QVector<DeviceSession*>& drives)
    : m_target(target)
{
    for (DeviceSession* d : drives)
        if (d && d != target)
            m_drives << d;
}

QVector<int> ReachedDrives::slaves() const
{
    QVector<int> out;
    for (const QPointer<DeviceSession>& d : m_drives)
        if (d)
            out << d->slave();
    return out;
}

const ParameterMeta* ReachedDrives::counterpart(const DeviceSession& drive,
                                                const ParameterMeta& meta)
{
    // The frame names an address, not a parameter: what the drive's own profile has there.
    const quint8 function = quint8(meta.writeFunction > 0 ? meta.writeFunction : 6);
    const ParameterMeta* own = drive.profile().parameterAt(function, meta.address);
    return own && own->address == meta.address && own->registerCount == meta.registerCount
               ? own
               : nullptr;
}

QString ReachedDrives::modelOf(const DeviceSession& drive)
{
    if (const ProfileVariant* v = drive.profile().variant(drive.variant()))
        return v->model;
    return drive.profile().variants.isEmpty()
               ? drive.profile().family.toUpper()
               : tr("%1, variant not known").arg(drive.profile().family.toUpper());
}

QString ReachedDrives::problem(const ParameterMeta& meta, const QVector<quint16>& registers,
                               const QStringList& companions, bool dependents) const
{
    if (!m_target)
        return QString();
    const int group = m_target->slave();
    QStringList problems;
    for (const QPointer<DeviceSession>& d : m_drives) {
        if (!d)
            continue;
        const ParameterMeta* own = counterpart(*d, meta);
        if (!own) {
            problems << tr("machine number %1 (%2) executes this write too (communication group "
                           "%3), but has no such setting at 0x%4")
                            .arg(d->slave())
                            .arg(modelOf(*d))
                            .arg(group)
                            .arg(meta.address, 4, 16, QLatin1Char('0'));
            continue;
        }
        const ValueContext context = d->context();
        QString unresolved;
        own->specFor(context, &unresolved);
        if (!unresolved.isEmpty() && !dependents)
            continue; // not known yet: the write reads it and checks again
        const double raw = ValueCodec::registersToRaw(*own, registers);
        QString refusal = ValueCodec::checkRaw(*own, raw, context);
        if (refusal.isEmpty() && dependents)
            refusal =
                DependentValues::problem(d->profile(), *own, qint64(raw), context, companions);
        if (refusal.isEmpty())
            continue;
        // The drive's refusal starts with the setting's name, which the message already has.
        const QString prefix = context.nameFor(own->name) + QStringLiteral(": ");
        if (refusal.startsWith(prefix))
            refusal = refusal.mid(prefix.size());
        problems << tr("machine number %1 (%2) executes this write too (communication group %3) "
                       "and does not allow it: %4")
                        .arg(d->slave())
                        .arg(modelOf(*d))
                        .arg(group)
                        .arg(refusal);
    }
    if (problems.isEmpty())
        return QString();
    return tr("%1: %2").arg(m_target->nameFor(meta.name), problems.join(QStringLiteral("; ")));
}

void ReachedDrives::check(const ParameterMeta& meta, const QVector<quint16>& registers,
                          const QStringList& companions,
                          std::function<void(const QString& refusal)> then) const
{
    if (isEmpty()) {
        then(QString());
        return;
    }
    const ReachedDrives self = *this;
    ensureKnown(
        {&meta}, companions, [self, &meta, registers, companions, then](const QString& unread) {
            if (!unread.isEmpty() && self.m_target)
                then(tr("%1 cannot be checked: %2").arg(self.m_target->nameFor(meta.name), unread));
            else
                then(self.problem(meta, registers, companions, true));
        });
}

DeviceSession::Done ReachedDrives::verifying(const ParameterMeta* meta,
                                             const QVector<quint16>& registers,
                                             DeviceSession::Done done) const
{
    // A command cannot be read back: what it did is for the caller to read (after a start,
    // the run states).
    if (isEmpty() || !meta->isReadable())
        return done;
    const ReachedDrives self = *this;
    return [self, meta, registers, done](const DeviceSession::Outcome& own) {
        // A refusal before sending reached nobody; anything sent may have reached them all.
        if (!own.sent || !self.m_target) {
            done(own);
            return;
        }
        const int group = self.m_target->slave();
        self.verify(*meta, registers, [own, done, group](const QVector<Result>& results) {
            DeviceSession::Outcome outcome = own;
            outcome.reached = results;
            QStringList differ;
            QStringList unread;
            for (const Result& r : results) {
                if (r.mismatch)
                    differ << r.text;
                else if (!r.verified)
                    unread << r.text;
            }
            if (!differ.isEmpty() && (own.ok || own.mismatch)) {
                // Acknowledged by the target, held differently by a drive it reached. (A write
                // the target did not confirm has failed already; what the others hold is said.)
                outcome.ok = false;
                outcome.mismatch = true;
            }
            if (!differ.isEmpty()) {
                const QString failed = tr("verification failed in communication group %1: %2")
                                           .arg(group)
                                           .arg(differ.join(QStringLiteral("; ")));
                outcome.error = outcome.error.isEmpty()
                                    ? failed
                                    : outcome.error + QStringLiteral("; ") + failed;
            }
            outcome.notVerified = unread.join(QStringLiteral("; "));
            outcome.verified = outcome.verified && differ.isEmpty() && unread.isEmpty();
            done(outcome);
        });
    };
}

void ReachedDrives::ensureKnown(const QVector<const ParameterMeta*>& metas,
                                const QStringList& companions,
                                std::function<void(const QString& problem)> then) const
{
    QVector<Read> queue;
    for (const QPointer<DeviceSession>& d : m_drives) {
        QStringList names;
        for (const ParameterMeta* meta : metas) {
            const ParameterMeta* own = d ? counterpart(*d, *meta) : nullptr;
            if (!own)
                continue;
            QStringList needed = own->controllingParameters();
            for (const QString& n : DependentValues::of(d->profile(), *own))
                if (!companions.contains(n))
                    needed << n;
            for (const QString& n : needed)
                if (!d->hasCached(n) && !names.contains(n))
                    names << n;
        }
        for (const QString& n : names)
            queue << Read{d, n};
    }
    readNext(m_target, queue, std::move(then));
}

void ReachedDrives::readNext(QPointer<DeviceSession> context, QVector<Read> queue,
                             std::function<void(const QString& problem)> then)
{
    while (!queue.isEmpty() && !queue.first().drive)
        queue.removeFirst();
    if (queue.isEmpty() || !context) {
        then(QString());
        return;
    }
    const Read next = queue.takeFirst();
    const ParameterMeta* meta = next.drive->profile().parameter(next.name);
    if (!meta || !meta->isReadable()) {
        readNext(context, queue, then);
        return;
    }
    const int slave = next.drive->slave();
    next.drive->client()->submit(
        BlockReader::requestFor(slave, *meta), context,
        [context, queue, then, next, meta, slave](const ModbusResult& r) {
            if (!r.ok()) {
                then(tr("reading %1 of machine number %2, which executes this write too, "
                        "failed: %3")
                         .arg(meta->label)
                         .arg(slave)
                         .arg(r.errorText()));
                return;
            }
            if (next.drive)
                next.drive->acceptRegisters(next.name, r.registers);
            readNext(context, queue, then);
        });
}

void ReachedDrives::verify(const ParameterMeta& meta, const QVector<quint16>& registers,
                           std::function<void(const QVector<Result>&)> done) const
{
    struct State
    {
        QVector<Result> results;
        int pending = 1;
        std::function<void(const QVector<Result>&)> done;
    };
    auto state = std::make_shared<State>();
    state->done = std::move(done);
    auto finish = [state] {
        if (--state->pending == 0)
            state->done(state->results);
    };
    for (const QPointer<DeviceSession>& d : m_drives) {
        if (!d || !m_target)
            continue;
        const int index = int(state->results.size());
        Result result;
        result.slave = d->slave();
        const ParameterMeta* own = counterpart(*d, meta);
        if (!own || !own->isReadable()) {
            result.text = tr("machine number %1: not verified (the setting cannot be read there)")
                              .arg(d->slave());
            state->results << result;
            continue;
        }
        state->results << result;
        ++state->pending;
        QPointer<DeviceSession> drive = d;
        d->client()->submit(
            BlockReader::requestFor(d->slave(), *own), m_target,
            [state, index, drive, own, registers, finish](const ModbusResult& r) {
                Result& out = state->results[index];
                if (!r.ok() || !drive) {
                    out.text = tr("machine number %1: not verified, reading it back failed: %2")
                                   .arg(out.slave)
                                   .arg(r.ok() ? tr("the drive was removed") : r.errorText());
                    finish();
                    return;
                }
                drive->acceptRegisters(own->name, r.registers);
                const ValueContext context = drive->context();
                out.value = ValueCodec::decode(*own, r.registers, context);
                out.held = ValueCodec::format(*own, out.value, context);
                const QString& holds = out.held;
                out.verified = r.registers == registers;
                out.mismatch = !out.verified;
                out.text =
                    out.verified
                        ? tr("machine number %1 holds %2").arg(out.slave).arg(holds)
                        : tr("machine number %1 holds %2, not %3")
                              .arg(out.slave)
                              .arg(holds, ValueCodec::format(
                                              *own, ValueCodec::decode(*own, registers, context),
                                              context));
                finish();
            });
    }
    finish();
}

} // namespace opentop
