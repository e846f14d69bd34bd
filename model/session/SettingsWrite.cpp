#include "model/session/SettingsWrite.h"

#include "model/profile/RoleEvaluator.h"
#include "model/profile/RunningData.h"
#include "model/profile/WriteOrder.h"
#include "model/session/DependentValues.h"
#include "model/session/ReachedDrives.h"
#include "model/session/SerialLock.h"
#include "model/session/SettingCheck.h"

#include <QHash>
#include <QPointer>
#include <algorithm>
#include <memory>

namespace opentop {

SettingsWrite::SettingsWrite(DeviceSession* session, bool confirmed, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_confirmed(confirmed)
{
}

QString SettingsWrite::add(const QString& name, const QString& text)
{
    for (const Item& a : m_items) {
        if (a.name == name) // which one would the drive keep? Neither is written
            return tr("%1 is given twice (%2=%3 and %4); give each setting once; nothing "
                      "written")
                .arg(name, name, a.text, name + QLatin1Char('=') + text);
    }
    Item item;
    item.name = name;
    item.text = text;
    m_items.append(item);
    return QString();
}

QStringList SettingsWrite::neededReads() const
{
    const Profile& profile = m_session->profile();
    QStringList needed;
    const auto want = [&](const QString& n) {
        if (!m_session->hasCached(n) && !needed.contains(n))
            needed << n;
    };
    for (const Item& a : m_items) {
        if (!a.meta)
            continue;
        for (const QString& c : a.meta->controllingParameters())
            want(c);
        // The settings that depend on this one are checked against its new value.
        for (const QString& d : DependentValues::of(profile, *a.meta))
            want(d);
        // The deceleration advice weighs an SPno's speed against its deceleration.
        QString field;
        if (const int spno = RunningData::spnoOf(a.name, &field); spno > 0) {
            for (const char* other : {"speed", "decel"}) {
                const QString n = RunningData::parameter(profile, spno, QLatin1String(other));
                if (!n.isEmpty() && n != a.name && profile.parameter(n)->isReadable())
                    want(n);
            }
        }
    }
    return needed;
}

void SettingsWrite::prepare(std::function<void(const Plan&)> done)
{
    const Profile& profile = m_session->profile();
    auto plan = std::make_shared<Plan>();
    for (Item& a : m_items) {
        a.meta = profile.parameter(a.name);
        if (!a.meta)
            plan->problems << tr("%1 has no parameter \"%2\"; see \"opentop-cli params --family "
                                 "%1\"")
                                  .arg(profile.family, a.name);
        else if (!a.meta->isWritable())
            plan->problems << tr("%1 is read-only").arg(a.name);
        else if (!a.meta->safety.isEmpty() && !m_confirmed)
            plan->problems
                << tr("%1 is a %2 command; add --yes to send it").arg(a.name, a.meta->safety);
    }
    // Writes that others depend on go first.
    QStringList given;
    for (const Item& a : m_items)
        given << a.name;
    const QStringList order = WriteOrder::of(profile, given);
    std::stable_sort(m_items.begin(), m_items.end(), [&order](const Item& x, const Item& y) {
        return order.indexOf(x.name) < order.indexOf(y.name);
    });
    const QStringList reads = plan->problems.isEmpty() ? neededReads() : QStringList();
    // Then what the checks need from the drive, and the values checked against it.
    const auto readAndCheck = [this, plan, reads, done] {
        if (!plan->problems.isEmpty() || reads.isEmpty()) {
            validate(*plan);
            done(*plan);
            return;
        }
        m_session->readMany(
            reads, [this, plan, reads, done](const DeviceSession::ReadManyOutcome& o) {
                if (o.failed > 0) {
                    plan->refusal = Refusal::Communication;
                    plan->problems << tr("cannot read %1 to check the values; nothing written")
                                          .arg(reads.join(QStringLiteral(", ")));
                    done(*plan);
                    return;
                }
                validate(*plan);
                done(*plan);
            });
    };
    // Parameter initialisation resets the line settings and control priority too: its
    // consequences are said before anything is sent, and what to do after it was sent.
    const ParameterMeta* init = RoleEvaluator::parameter(profile, QStringLiteral("parameterInit"));
    if (!init || std::none_of(m_items.begin(), m_items.end(),
                              [init](const Item& a) { return a.name == init->name; })) {
        readAndCheck();
        return;
    }
    auto initialiser = std::make_shared<ParameterInitialiser>(m_session);
    initialiser->check(
        [this, plan, initialiser, readAndCheck](const ParameterInitialiser::Plan& p) {
            plan->consequences = p.consequences;
            if (!p.refusal.isEmpty())
                plan->problems << p.refusal;
            m_init = p;
            readAndCheck();
        });
}

void SettingsWrite::validate(Plan& plan)
{
    if (plan.problems.isEmpty()) {
        const Profile& profile = m_session->profile();
        QHash<QString, qint64> pending;
        const ValueContext overlay = SettingCheck::overlay(
            m_session->context(), [&pending](const QString& n) -> std::optional<qint64> {
                const auto it = pending.constFind(n);
                return it == pending.cend() ? std::nullopt : std::optional<qint64>(*it);
            });
        QStringList names;
        for (const Item& a : m_items)
            names << a.name;
        for (Item& a : m_items) {
            const SettingCheck c = SettingCheck::of(profile, *a.meta, a.text, overlay, names);
            if (!c.ok) {
                plan.problems << c.error;
                continue;
            }
            a.registers = c.registers;
            if (!c.warning.isEmpty())
                plan.warnings << c.warning;
            // It can shut this program out of the drive's configuration: only on request.
            if (!c.lock.isEmpty() && !m_confirmed)
                plan.problems << c.lock + QLatin1Char(' ') + tr("Add --yes to set it.");
            else if (!c.lock.isEmpty())
                plan.warnings << c.lock;
            if (!c.dependent.isEmpty())
                plan.problems << c.dependent;
            pending.insert(a.name, c.raw);
        }
        // Advice, not a refusal: the manual's deceleration rule for the values as written.
        for (const Item& a : m_items) {
            if (!pending.contains(a.name))
                continue;
            const QString w =
                RunningData::warningFor(profile, a.name, pending.value(a.name), overlay);
            if (!w.isEmpty() && !plan.advice.contains(w))
                plan.advice << w;
        }
    }
    if (!plan.problems.isEmpty() && plan.refusal == Refusal::None)
        plan.refusal = Refusal::Invalid;
    m_prepared = plan.refusal == Refusal::None;
}

void SettingsWrite::checkReached(
    std::function<void(const QStringList& problems, bool communication)> done)
{
    auto reached = std::make_shared<ReachedDrives>(m_session, m_session->reachedDrives());
    if (reached->isEmpty()) {
        done({}, false);
        return;
    }
    QVector<const ParameterMeta*> metas;
    QStringList names;
    for (const Item& a : m_items) {
        metas << a.meta;
        names << a.name;
    }
    reached->ensureKnown(metas, names, [this, reached, names, done](const QString& problem) {
        if (!problem.isEmpty()) {
            done({problem}, true);
            return;
        }
        QStringList problems;
        for (const Item& a : m_items) {
            const QString refused = reached->problem(*a.meta, a.registers, names, true);
            if (!refused.isEmpty())
                problems << refused;
        }
        done(problems, false);
    });
}

void SettingsWrite::write(std::function<void()> done)
{
    if (!m_prepared) { // nothing is sent that prepare() did not accept
        done();
        return;
    }
    writeFrom(0, std::move(done));
}

void SettingsWrite::cancel()
{
    if (m_cancelled)
        return;
    m_cancelled = true;
    // The value in flight may or may not have reached the drive; the rest were never sent.
    for (int i = std::max(0, m_current); i < m_items.size(); ++i) {
        DeviceSession::Outcome& o = m_items[i].outcome;
        if (o.ok || !o.error.isEmpty())
            continue;
        if (i == m_current) {
            o.unconfirmed = true;
            o.error = tr("interrupted as it was sent");
        } else {
            o.error = tr("not written (interrupted)");
        }
    }
}

void SettingsWrite::writeFrom(int index, std::function<void()> done)
{
    m_current = index;
    if (index >= m_items.size() || m_cancelled) {
        done();
        return;
    }
    DeviceSession::WriteOptions options;
    options.explicitCommand = m_confirmed;
    for (int later = index + 1; later < m_items.size(); ++later)
        options.companions << m_items.at(later).name;
    const Item& a = m_items.at(index);
    // A cancelled write's late answer ends here: nothing more is sent, nobody is called.
    m_session->write(
        a.name, a.text, options,
        [self = QPointer<SettingsWrite>(this), index, done](const DeviceSession::Outcome& o) {
            if (!self || self->m_cancelled)
                return;
            self->m_items[index].outcome = o;
            self->writeFrom(index + 1, done);
        });
}

bool SettingsWrite::initialisationSent() const
{
    const ParameterMeta* init =
        RoleEvaluator::parameter(m_session->profile(), QStringLiteral("parameterInit"));
    return init && m_init && std::any_of(m_items.begin(), m_items.end(), [init](const Item& a) {
               return a.name == init->name && a.outcome.ok;
           });
}

} // namespace opentop
