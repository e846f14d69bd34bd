#include "model/run/RunnerStates.h"

#include "model/ModelLog.h"

#include <QElapsedTimer>
#include <QTimer>
#include <memory>

namespace opentop {

RunnerStates::RunnerStates(const QString& runner, QObject* parent)
    : QObject(parent)
    , m_runner(runner)
{
}

void RunnerStates::add(int state, const char* name, Enter enter)
{
    Q_ASSERT(!find(state));
    m_states.append({state, name, std::move(enter)});
}

const RunnerStates::State* RunnerStates::find(int state) const
{
    for (const State& s : m_states) {
        if (s.id == state)
            return &s;
    }
    return nullptr;
}

QString RunnerStates::nameOf(int state) const
{
    const State* s = find(state);
    return s ? QString::fromLatin1(s->name) : QString();
}

void RunnerStates::start(int first)
{
    leave();
    m_motion = false;
    m_everMoved = false;
    m_trail.clear();
    const quint64 entry = m_entry;
    // Not entered yet: a guard or go() before the first state would see m_state < 0.
    QTimer::singleShot(0, this, [this, entry, first] {
        if (entry == m_entry)
            go(first);
    });
}

void RunnerStates::startNow(int first)
{
    leave();
    m_motion = false;
    m_everMoved = false;
    m_trail.clear();
    go(first);
}

void RunnerStates::leave()
{
    ++m_entry;
    m_state = -1;
}

void RunnerStates::go(int state)
{
    const State* s = find(state);
    const QString from = stateName();
    leave();
    if (!s) {
        qCWarning(lcModel) << m_runner << "has no state" << state << "after" << from;
        return;
    }
    m_state = state;
    m_trail << QString::fromLatin1(s->name);
    qCDebug(lcModel).noquote() << m_runner << (from.isEmpty() ? QStringLiteral("start") : from)
                               << "->" << s->name;
    emit entered(state, m_trail.last());
    if (s->enter)
        s->enter();
}

void RunnerStates::end()
{
    if (m_state >= 0)
        qCDebug(lcModel).noquote() << m_runner << stateName() << "-> end";
    leave();
}

void RunnerStates::after(int ms, std::function<void()> f)
{
    QTimer::singleShot(ms, this, guard(std::move(f)));
}

void RunnerStates::every(int periodMs, std::function<void(std::function<void()> again)> round)
{
    auto since = std::make_shared<QElapsedTimer>();
    since->start();
    // The loop holds itself only weakly: the round in progress (its answer's callback or the
    // timer it waits on) holds it, so a loop whose state ended frees itself.
    auto loop = std::make_shared<std::function<void()>>();
    *loop = guard([this, periodMs, since, round = std::move(round),
                   weak = std::weak_ptr<std::function<void()>>(loop)] {
        const auto self = weak.lock();
        if (!self)
            return;
        round(guard([this, periodMs, since, self] {
            const int waitMs =
                periodMs > 0 ? std::max(0, periodMs - int(since->elapsed() % periodMs)) : 0;
            after(waitMs, [self] { (*self)(); });
        }));
    });
    (*loop)();
}

} // namespace opentop
