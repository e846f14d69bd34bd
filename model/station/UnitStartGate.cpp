#include "model/station/UnitStartGate.h"

#include "transport/ModbusClient.h"

#include <QTimer>
#include <utility>

namespace opentop {

UnitStartGate::UnitStartGate(const ProfileRegistry& registry, QObject* parent)
    : QObject(parent)
    , m_registry(registry)
{
}

UnitStartGate::~UnitStartGate() = default;

QString UnitStartGate::pendingSerial() const
{
    return m_pending ? m_pending->unit.options.serial : QString();
}

bool UnitStartGate::start(const Unit& unit, Done done)
{
    if (m_pending)
        return false;
    m_pending = std::make_unique<Pending>(Pending{unit, std::move(done)});
    const quint64 token = ++m_token;
    RetestPolicy::check(unit.options.writer, unit.recipe.retest, unit.options.serial,
                        unit.options.recipeChecksum, this,
                        [this, token](const RetestPolicy::Decision& d) {
                            if (token == m_token && m_pending) // else cancelled since
                                retestChecked(d);
                        });
    return true;
}

bool UnitStartGate::cancel(const QString& reason)
{
    if (!m_pending)
        return false;
    ++m_token;
    Pending pending = std::move(*std::exchange(m_pending, nullptr));
    end(std::move(pending), Outcome::Kind::Cancelled,
        reason.isEmpty() ? tr("cancelled before it started") : reason);
    return true;
}

void UnitStartGate::retestChecked(const RetestPolicy::Decision& d)
{
    using Kind = RetestPolicy::Decision::Kind;
    m_decision = d;
    if (d.kind == Kind::Refused ||
        (d.kind == Kind::NeedsTechnician && !m_pending->unit.technicianAllows)) {
        Pending pending = std::move(*std::exchange(m_pending, nullptr));
        end(std::move(pending),
            d.kind == Kind::Refused ? Outcome::Kind::RetestRefused : Outcome::Kind::NeedsTechnician,
            d.reason);
        return;
    }
    m_pending->retestPassed = true;
    const quint64 token = m_token;
    if (m_pending->unit.retestPassed)
        m_pending->unit.retestPassed(d);
    if (!m_pending || token != m_token) // cancelled from the callback
        return;
    // Only now: the retest rules are checked before anything is sent, a bus included.
    ModbusClient* client = m_pending->unit.client ? m_pending->unit.client() : nullptr;
    if (!client || (m_safe && !m_safeState))
        proceed();
    else
        makeSafe(client, m_pending->unit.recipe); // or the one under way: proceed() after it
}

void UnitStartGate::proceed()
{
    Pending pending = std::move(*std::exchange(m_pending, nullptr));
    ModbusClient* client = pending.unit.client ? pending.unit.client() : nullptr;
    if (!client) {
        end(std::move(pending), Outcome::Kind::NotConnected, tr("not connected to a bus"));
        return;
    }
    if (!m_safe) {
        end(std::move(pending), Outcome::Kind::Unsafe,
            tr("a drive of the station is not safe: %1")
                .arg(PositionSafety::blockingText(m_safety)));
        return;
    }
    auto* run = new EolRun(client, m_registry, pending.unit.recipe, pending.unit.options);
    m_run = run;
    m_client = client;
    if (pending.unit.made)
        pending.unit.made(run, client);
    run->start(pending.unit.finished);
    end(std::move(pending), Outcome::Kind::Begun, QString());
}

void UnitStartGate::end(Pending pending, Outcome::Kind kind, const QString& message)
{
    if (pending.done)
        pending.done(Outcome{kind, pending.unit.options.serial, message});
}

void UnitStartGate::makeSafe(ModbusClient* client, const Recipe& recipe)
{
    if (!client || m_safeState || (m_run && m_run->isRunning()))
        return;
    m_client = client;
    m_safeState = new StationSafeState(client, m_registry, recipe, this);
    m_safeState->setStopTiming(m_stopTiming);
    emit safetyChanged();
    m_safeState->run([this](const QVector<PositionSafety>& found) {
        m_safeState->deleteLater();
        m_safeState = nullptr;
        m_safety = found;
        m_safe = PositionSafety::blockingText(found).isEmpty();
        emit safetyChanged();
        // A unit still waiting for its retest answer goes on only once that allows it.
        if (m_pending && m_pending->retestPassed)
            proceed();
    });
}

void UnitStartGate::unitEnded(const UnitRecord& record, const Recipe& recipe)
{
    if (record.status != UnitStatus::Aborted && record.status != UnitStatus::Error &&
        !(m_run && !m_run->unconfirmedStops().isEmpty()))
        return;
    m_safe = false;
    QTimer::singleShot(0, this, [this, recipe] {
        if (m_client)
            makeSafe(m_client, recipe);
    });
}

} // namespace opentop
