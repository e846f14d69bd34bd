#pragma once

#include "model/eol/EolDriveRun.h"
#include "model/eol/Recipe.h"
#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <functional>
#include <memory>

namespace opentop {

class ModbusClient;
class ProfileRegistry;
class ResultWriter;
class RunControl;
class TrafficLog;

// One unit through the end-of-line station: every drive of the recipe at once (EolDriveRun),
// so one drive ramps while the next is written and the bus is shared between them; the first
// failure ends the others (their motors stopped) and is the unit's reason. With a ResultWriter,
// the unit's record is committed as running before anything is sent and completed in one
// transaction at the end, so a station killed mid-unit never leaves a partial pass; the run
// waits for each answer without making its thread wait.
class EolRun : public QObject
{
    Q_OBJECT
public:
    struct Options
    {
        QString serial;
        QString station;
        QString operatorName;
        QString recipeChecksum; // as the recipe file carries it
        QString approvalId;     // the approval it runs under (empty: unmanaged station)
        QString approver;
        // This unit's per-unit values: machine number → parameter → engineering value.
        QHash<int, QHash<QString, double>> unitValues;
        // Variants stated by the person running the unit (eol run --variant), by machine
        // number: taken as confirmed when the drive cannot prove its own, refused when it does
        // and differs.
        QHash<int, QString> assertedVariants;
        EolStepRunner::Timing timing;
        ResultWriter* writer = nullptr; // none: nothing recorded
        TrafficLog* traffic = nullptr;  // decoded traffic around a failure goes into the record
        int trafficLines = 60;
    };
    using Done = std::function<void(const UnitRecord&)>;

    EolRun(ModbusClient* client, const ProfileRegistry& registry, const Recipe& recipe,
           const Options& options, QObject* parent = nullptr);
    ~EolRun() override;

    // `done` runs once with the unit's record, never before start() returns, and after the
    // record is stored. A record that could not be stored says so in storeError().
    void start(Done done);
    // Cancels the unit: every motor that may be turning is stopped first.
    void cancel(const QString& reason = QString());
    // The port is gone: the same as cancel, naming it.
    void connectionLost(const QString& error);
    bool isRunning() const { return bool(m_done); }
    const UnitRecord& record() const { return m_record; }
    QString storeError() const { return m_storeError; }
    // The verdict is kept in the station's spool: safe, not yet in the results database.
    bool spooled() const { return m_spooled; }
    // Drives whose motor may still be turning after the run (not confirmed stopped).
    QStringList unconfirmedStops() const { return m_unconfirmed; }
    qint64 elapsedMs() const { return m_elapsed.elapsed(); }
    // Machine numbers whose alarm was active before the test (a reset may let it run again).
    QVector<int> latchedAlarms() const { return m_latchedAlarms; }

signals:
    void phaseChanged(int machineNumber, opentop::EolDriveRun::Phase phase, const QString& text);
    void measured(const opentop::Measurement& measurement);
    void speedSampled(int machineNumber, double speed, const QString& unit);
    // The run waits for the results database (what for, in words; empty: no longer), so that
    // a slow one shows.
    void recording(const QString& what);
    void finished(const opentop::UnitRecord& record);

private:
    // Why the recipe or this unit's values may not be run; empty when they may.
    QString problemOf() const;
    void startDrives();
    void driveDone(EolDriveRun* drive);
    void finish();
    void complete(); // the record is stored (or could not be): the run ends
    QStringList trafficLines() const;

    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
    Recipe m_recipe;
    Options m_options;
    RunControl* m_run;
    QVector<EolDriveRun*> m_drives;
    int m_remaining = 0;
    QString m_firstFailure;
    bool m_cancelled = false;
    bool m_stationError = false; // the first failure is the station's (UnitStatus::Error)
    QVector<int> m_latchedAlarms;
    bool m_recording = false; // the record is being completed: the unit's work is over
    QStringList m_unconfirmed;
    UnitRecord m_record;
    QString m_storeError;
    bool m_spooled = false;
    QElapsedTimer m_elapsed;
    Done m_done;
};

} // namespace opentop
