#pragma once

#include "model/eol/EolRun.h"
#include "model/eol/Recipe.h"
#include "model/eol/RetestPolicy.h"
#include "model/eol/StationSafeState.h"
#include "model/run/StopConfirmer.h"

#include <QObject>
#include <QPointer>
#include <functional>
#include <memory>

namespace opentop {

class ModbusClient;
class ProfileRegistry;

// Whether a unit may begin at an end-of-line station: the one sequence of the operator screen
// (EolStation) and `eol run`. First the recipe's retest rules on the serial's recorded verdicts
// (RetestPolicy), before anything is sent; then the recipe's positions safe (StationSafeState: a
// motor a killed station left turning is stopped, one that cannot be holds every unit back);
// then the unit begun (EolRun: its record committed as running before anything is sent). The
// outcome says which step held a unit back and why, as data: the front ends show it, and ask
// what only they can ask (a technician on the screen, --retest on the command line).
// It also keeps what making the positions safe found, across units: the screen does it when
// production starts and again only after a unit that did not end cleanly.
class UnitStartGate : public QObject
{
    Q_OBJECT
public:
    struct Outcome
    {
        enum class Kind
        {
            Begun,           // the unit's run started (it records the unit first)
            RetestRefused,   // the recipe never tests this serial again
            NeedsTechnician, // a retest only a technician may allow
            NotConnected,    // no bus to make the positions safe on or to test with
            Unsafe,          // a position is not safe (PositionSafety::blocksUnits)
            Cancelled        // cancel() before it began: nothing was sent for it
        };
        Kind kind = Kind::Begun;
        QString serial;
        QString message; // why it did not begin, for the operator; empty when begun
    };
    struct Unit
    {
        Recipe recipe;
        // The run's options; their serial, checksum and writer also serve the retest rules.
        EolRun::Options options;
        bool technicianAllows = false; // a retest the rules leave to a technician is allowed
        // The bus, asked when the retest rules let the unit on and again before it begins
        // (`eol run` connects only then); null: not connected.
        std::function<ModbusClient*()> client;
        // The retest rules let the unit on (a note, or a technician's override): said before
        // the positions are made safe.
        std::function<void(const RetestPolicy::Decision&)> retestPassed;
        // The unit's run, made and not started yet, without a parent: the front end takes it
        // and connects to it.
        std::function<void(EolRun* run, ModbusClient* client)> made;
        EolRun::Done finished; // the unit's record (EolRun::start)
    };
    using Done = std::function<void(const Outcome&)>;

    explicit UnitStartGate(const ProfileRegistry& registry, QObject* parent = nullptr);
    ~UnitStartGate() override;

    // Takes `unit` through retest → safe → begin; `done` once with the outcome, never inside
    // start(). False (nothing done) while another unit waits.
    bool start(const Unit& unit, Done done);
    bool isPending() const { return bool(m_pending); }
    QString pendingSerial() const;
    // The unit that waits is dropped (nothing was sent for it): its `done` says Cancelled with
    // `reason`. False when none waits.
    bool cancel(const QString& reason = QString());
    // The last retest decision of a unit that was not cancelled (its attempt number).
    const RetestPolicy::Decision& decision() const { return m_decision; }

    // Puts `recipe`'s positions in a safe state unless no client, that is under way or a unit
    // this gate began still runs; a unit that waits for it goes on once it is done.
    void makeSafe(ModbusClient* client, const Recipe& recipe);
    bool isMakingSafe() const { return bool(m_safeState); }
    bool isSafe() const { return m_safe; }
    // Made safe again before the next unit (a new recipe, a lost link).
    void forgetSafe() { m_safe = false; }
    // A unit this gate began ended: one that did not end cleanly (aborted, a station error, a
    // motor not confirmed stopped) may have left a motor turning or a drive in communication
    // priority, so `recipe`'s positions are made safe again at once, before the next unit.
    void unitEnded(const UnitRecord& record, const Recipe& recipe);
    const QVector<PositionSafety>& safety() const { return m_safety; }
    void setStopTiming(const StopConfirmer::Timing& timing) { m_stopTiming = timing; }

signals:
    void safetyChanged(); // making safe began or ended (safety() holds what it found)

private:
    struct Pending
    {
        Unit unit;
        Done done;
        bool retestPassed = false; // waits for the positions to be made safe
    };
    void retestChecked(const RetestPolicy::Decision& d);
    void proceed(); // the positions were checked: the unit begins, or is held back
    void end(Pending pending, Outcome::Kind kind, const QString& message);

    const ProfileRegistry& m_registry;
    std::unique_ptr<Pending> m_pending;
    quint64 m_token = 0; // a retest answer for a unit since cancelled is dropped
    RetestPolicy::Decision m_decision;
    QPointer<EolRun> m_run;          // the last unit begun
    QPointer<ModbusClient> m_client; // the bus it was begun or made safe on
    QPointer<StationSafeState> m_safeState;
    bool m_safe = false;
    QVector<PositionSafety> m_safety;
    StopConfirmer::Timing m_stopTiming;
};

} // namespace opentop
