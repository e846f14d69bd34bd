#include "ui/tuning/TuningGains.h"

#include "model/tuning/TuningRunner.h"

#include <QPointer>

namespace opentop {

TuningGains::TuningGains(TuningRunner* runner, QObject* parent)
    : QObject(parent)
    , m_runner(runner)
{
}

void TuningGains::setBusy(bool busy)
{
    m_busy = busy;
    emit busyChanged();
}

void TuningGains::refresh()
{
    const QPointer<TuningGains> self(this);
    m_runner->readGains([self](bool ok, const PidGains& gains, const QString&) {
        if (!self || !ok)
            return;
        self->m_present = gains;
        emit self->presentChanged(gains);
    });
}

void TuningGains::write(const PidGains& gains, const Then& then)
{
    setBusy(true);
    const QPointer<TuningGains> self(this);
    m_runner->writeGains(gains, [self, then](bool ok, const PidGains& read, const QString& error) {
        if (!self)
            return;
        if (ok) {
            self->m_present = read;
            emit self->presentChanged(read);
        } else {
            emit self->message(tr("Writing the gains failed: %1").arg(error), true);
        }
        // Idle before `then` (which may go on), shown after it (which changes the state).
        self->m_busy = false;
        if (then)
            then(ok);
        if (self)
            emit self->busyChanged();
    });
}

void TuningGains::accept(const PidGains& proposal, const PidGains& before, const Then& then)
{
    if (!m_changed)
        m_before = before;
    write(proposal, [this, then](bool ok) {
        if (ok) {
            m_changed = true;
            m_accepted = true;
            emit message(tr("Proposal written (temporary until stored)."), false);
        }
        if (then)
            then(ok);
    });
}

void TuningGains::restore(const QString& why, const Then& then)
{
    if (!m_changed || !m_before) {
        m_accepted = false;
        if (then)
            then(true);
        return;
    }
    const PidGains before = *m_before;
    write(before, [this, why, before, then](bool ok) {
        if (ok) {
            m_changed = false;
            m_accepted = false;
            emit message(
                tr("%1: the gains before were written back (%2).").arg(why, before.toString()),
                false);
        }
        if (then)
            then(ok);
    });
}

void TuningGains::store(const Then& then)
{
    setBusy(true);
    const QPointer<TuningGains> self(this);
    m_runner->storeGains([self, then](bool ok, const QString& error) {
        if (!self)
            return;
        if (ok) {
            self->m_changed = false;
            self->m_accepted = false;
            self->m_before.reset();
            emit self->message(tr("Gains stored in the drive."), false);
        } else {
            emit self->message(tr("Storing the gains failed: %1").arg(error), true);
        }
        self->m_busy = false;
        if (then)
            then(ok);
        if (self)
            emit self->busyChanged();
    });
}

} // namespace opentop
