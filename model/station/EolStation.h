#pragma once

#include "model/eol/EolRun.h"
#include "model/eol/Recipe.h"
#include "model/eol/RetestPolicy.h"
#include "model/eol/StationLease.h"
#include "model/eol/StationSafeState.h"
#include "model/eol/UnitRecord.h"
#include "model/station/LatchedAlarms.h"
#include "model/station/StationRecipe.h"
#include "model/station/StationResults.h"
#include "model/station/UnitStartGate.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>
#include <memory>
#include <optional>

namespace opentop {

class ModbusClient;
class StationYield;
class StationAccess;
class TrafficLog;

// An end-of-line station as the operator screen drives it: one recipe, one results database
// (StationResults), units one after another (UnitStartGate, then EolRun), this shift's counters
// and last units. The screen only shows what this says; `eol run` shares the gate and the run.
class EolStation : public QObject
{
    Q_OBJECT
public:
    explicit EolStation(QObject* parent = nullptr);
    ~EolStation() override;

    // Loads and checks a recipe; false with the reasons (every checker problem) when it may not
    // be run. The recipe stays as it was on failure.
    bool loadRecipe(const QString& path, QStringList* problems);
    bool hasRecipe() const { return m_recipe.has(); }
    const Recipe& recipe() const { return m_recipe.recipe(); }
    QString recipePath() const { return m_recipe.path(); }
    QString recipeChecksum() const { return m_recipe.checksum(); } // what an approval names
    bool loadUnitValues(const QString& path, QString* error)
    {
        return m_recipe.loadUnitValues(path, error);
    }
    bool hasUnitValues() const { return m_recipe.hasUnitValues(); }
    // Why `serial`, as scanned, may not be tested under the recipe (SerialRule); empty when it
    // may. start() asks it too.
    QString serialProblem(const QString& serial) const;
    // Per-unit values the operator types (the recipe's "operator" ones) for the next unit.
    QVector<QPair<int, RecipeUnitValue>> operatorValues() const
    {
        return m_recipe.operatorValues();
    }

    // Opens the results database (StationResults: tried again by itself until it opens); the
    // station's leftovers from a crash become interrupted. databaseOpened() answers each try.
    void openDatabase(const QString& url);
    // The same, waiting in a local event loop (start-up, before the window); no databaseOpened().
    bool openDatabaseAndWait(const QString& url, QString* error);
    QString databaseText() const { return m_results->text(); }
    QString databaseError() const { return m_results->error(); } // empty once it is open
    QString databaseUrl() const { return m_results->url(); }     // as given to openDatabase()
    bool hasDatabase() const; // open, and whether it has users is known (access())
    bool isOpeningDatabase() const;
    // The station's name in every record (default: the host's name). A database already open is
    // opened again under the new name; refused (false) while a unit runs or for a blank name.
    bool setStation(const QString& station);
    QString station() const { return m_station; }
    // Typed on an unmanaged station; a managed one records the logged-in user (access()).
    void setOperatorName(const QString& name) { m_operator = name; }
    QString operatorName() const { return m_operator; } // as typed on a station without users
    // Users, the login and the recipe's approval (docs/eol-results.md): start() refuses a unit
    // on a managed station without a logged-in user or an approved recipe.
    StationAccess* access() const { return m_access; }
    void setTiming(const EolStepRunner::Timing& timing) { m_timing = timing; }

    // Starts a unit: false with *error (and nothing sent) when no recipe, a serial the recipe
    // refuses (serialProblem(), taken exactly as given: not trimmed), no database, a per-unit
    // value missing or not allowed, or a unit already running. `typed`: the operator's values.
    // Then UnitStartGate: the retest rules (a retest that needs a technician only with
    // `retestBy`, who allowed it), the positions made safe, the unit begun: unitStarted(), or
    // startRefused() / retestNeedsTechnician() say why not.
    bool start(ModbusClient* client, TrafficLog* traffic, const QString& serial,
               const QHash<int, QHash<QString, double>>& typed, QString* error,
               const QString& retestBy = QString());
    // The last serial start() was given, again, with the values it was given (a retest a
    // technician allowed, `retestBy` naming them).
    bool startAgain(ModbusClient* client, const QString& retestBy, QString* error);
    QString lastSerial() const { return m_lastStart.serial; }
    void cancel(const QString& reason = QString());
    void connectionLost(const QString& error);
    bool isRunning() const { return m_run && m_run->isRunning(); }
    // A unit start() accepted that waits for the drives to be made safe.
    bool isStarting() const { return m_gate->isPending(); }
    QString startingSerial() const { return m_gate->pendingSerial(); }
    EolRun* run() const { return m_run; }
    qint64 elapsedMs() const { return m_run ? m_run->elapsedMs() : 0; }
    // This station's figures for this recipe version in this shift, as the database holds them.
    StationYield* yield() const { return m_yield; }
    // The last retest decision (its attempt number) for the unit started last.
    const RetestPolicy::Decision& lastDecision() const { return m_gate->decision(); }
    // The last unit's alarms latched before its test (LatchedAlarms): the operator may reset.
    QVector<int> latchedAlarms() const { return m_alarms->machineNumbers(); }
    bool isResettingAlarms() const { return m_alarms->isResetting(); }
    // Resets those alarms (each drive's reset rules) and, when all are cleared, starts the same
    // serial again with the values it was given.
    void resetAlarmsAndRetry(ModbusClient* client);
    const QVector<UnitRecord>& lastUnits() const { return m_last; } // newest first
    QStringList unconfirmedStops() const { return m_unconfirmed; }
    QString storeError() const { return m_results->storeError(); }
    // The last unit's verdict is not recorded yet (StationResults): no unit starts until it is.
    bool hasUnsavedResult() const { return m_results->unsaved().has_value(); }
    const std::optional<UnitRecord>& unsavedResult() const { return m_results->unsaved(); }
    int nextRetrySeconds() const { return m_results->nextRetrySeconds(); }
    void retryUnsavedNow() { m_results->retryUnsavedNow(); }
    // Puts the recipe's positions in a safe state (UnitStartGate::makeSafe): when production
    // starts; units wait until it was done and found nothing unsafe.
    void makeSafe(ModbusClient* client);
    bool isMakingSafe() const { return m_gate->isMakingSafe(); }
    bool isSafe() const { return m_gate->isSafe(); }
    const QVector<PositionSafety>& safety() const { return m_gate->safety(); }
    void setStopTiming(const StopConfirmer::Timing& timing) { m_gate->setStopTiming(timing); }
    // The last verdict is kept in the station's spool, not yet in the results database.
    bool lastResultSpooled() const { return m_results->lastSpooled(); }
    // Records in the spool, waiting for the results database, and why.
    int resultsWaiting() const { return m_results->waiting(); }
    QString resultsWaitingError() const { return m_results->waitingError(); }
    void sendWaitingResultsNow() { m_results->sendWaitingNow(); }
    // Units of this station that a process now gone left running (found when the database
    // opened): interrupted in the database, and named on the screen.
    const QVector<StationLease::Leftover>& interruptedUnits() const
    {
        return m_results->interrupted();
    }

signals:
    void unitStarted(const QString& serial);
    void phaseChanged(int machineNumber, opentop::EolDriveRun::Phase phase, const QString& text);
    void measured(const opentop::Measurement& measurement);
    void speedSampled(int machineNumber, double speed, const QString& unit);
    void recording(const QString& what); // EolRun::recording
    void unitFinished(const opentop::UnitRecord& record);
    // The unsaved verdict was recorded at last (recorded() true), or another try failed.
    void unsavedResultChanged(bool recorded, const QString& error);
    void resultsWaitingChanged(int waiting, const QString& error);
    void interruptedFound(const QVector<opentop::StationLease::Leftover>& units);
    void safetyChanged(); // making safe began or ended (safety() holds what it found)
    // A unit start() accepted while the drives were made safe did not start after all.
    void startRefused(const QString& serial, const QString& why);
    // The serial was tested before and the recipe wants a technician to allow another test.
    void retestNeedsTechnician(const QString& serial, const QString& why);
    // A retest that needed a technician was allowed by `by` (recorded in the audit trail).
    void retestAllowed(const QString& serial, const QString& why, const QString& by);
    void alarmResetStarted(const QVector<int>& machineNumbers);
    void alarmResetFinished(bool cleared, const QStringList& texts);
    // The answer to openDatabase(): `error` names the database and why not.
    void databaseOpened(bool ok, const QString& error);

private:
    void finished(const UnitRecord& record);
    void refreshYield(); // the shift's figures again, as the database holds them
    // The gate began the unit: its run is the station's, the screen follows it.
    void begin(EolRun* run, ModbusClient* client);

    StationRecipe m_recipe;                    // the recipe and each unit's values
    std::unique_ptr<StationResults> m_results; // the database and verdicts not recorded yet
    StationAccess* m_access;
    QString m_station;
    QString m_operator;
    EolStepRunner::Timing m_timing;
    QPointer<EolRun> m_run;
    StationYield* m_yield;
    UnitStartGate* m_gate; // retest → safe → begin; what making safe found
    struct LastStart
    {
        QString serial;
        QHash<int, QHash<QString, double>> typed;
        TrafficLog* traffic = nullptr;
    } m_lastStart;
    LatchedAlarms* m_alarms; // before a test, and their reset on request
    QVector<UnitRecord> m_last;
    QStringList m_unconfirmed;
};

} // namespace opentop
