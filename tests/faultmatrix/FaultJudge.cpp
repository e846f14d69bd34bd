#include "tests/faultmatrix/FaultJudge.h"

#include "tests/faultmatrix/MatrixSim.h"

#include <QJsonArray>
#include <QRegularExpression>

namespace opentop::faultmatrix {

namespace {

QString registersText(const QVector<quint16>& registers)
{
    QStringList parts;
    for (quint16 r : registers)
        parts << QString::number(r);
    return QStringLiteral("[%1]").arg(parts.join(QLatin1Char(',')));
}

QJsonObject driveReport(const QJsonObject& report, int slave)
{
    for (const QJsonValue& d : report.value(QStringLiteral("drives")).toArray()) {
        if (d.toObject().value(QStringLiteral("slave")).toInt() == slave)
            return d.toObject();
    }
    return {};
}

QJsonObject itemOf(const QJsonObject& drive, const QString& parameter)
{
    for (const QJsonValue& i : drive.value(QStringLiteral("items")).toArray()) {
        if (i.toObject().value(QStringLiteral("parameter")).toString() == parameter)
            return i.toObject();
    }
    return {};
}

void gaveUp(const QString& what, const CliRun& run, FaultCounts* c)
{
    ++c->gaveUp;
    const QString reason = run.reason();
    c->gaveUpReasons << QStringLiteral("%1: exit %2: %3")
                            .arg(what)
                            .arg(run.code)
                            .arg(reason.isEmpty() ? QStringLiteral("(no reason given)") : reason);
    if (reason.isEmpty()) {
        ++c->unreported;
        c->findings << QStringLiteral("%1 exited %2 without saying why").arg(what).arg(run.code);
    }
    if (!FaultJudge::documentedExit(run.code)) {
        ++c->unreported;
        c->findings << QStringLiteral("%1 ended with exit %2, not a documented exit code")
                           .arg(what)
                           .arg(run.code);
    }
}

} // namespace

bool FaultJudge::documentedExit(int code)
{
    return code == 0 || code == 1 || code == 2 || code == 3 || code == 4 || code == 130;
}

void FaultJudge::backupDone(const QVector<Setting>& file, const Truth& truth,
                            const QVector<int>& asked, const QString& path, const CliRun& run,
                            FaultCounts* c)
{
    for (const Setting& s : file) {
        ++c->backupValues;
        const QVector<quint16> t = truth.value(MatrixSim::key(s.slave, s.name));
        if (t != s.registers) {
            ++c->backupDiffer;
            c->findings << QStringLiteral("backup: drive %1 %2: file %3, drive %4")
                               .arg(s.slave)
                               .arg(s.name, registersText(s.registers), registersText(t));
        }
    }
    const QVector<int> held = BackupValues::slaves(file);
    for (int slave : asked) {
        if (!held.contains(slave)) {
            ++c->unreported;
            c->findings
                << QStringLiteral("backup exited 0 without drive %1 in the file").arg(slave);
        }
    }
    if (!run.out.contains(QStringLiteral("wrote %1: %2 drive").arg(path).arg(asked.size()))) {
        ++c->unreported;
        c->findings << QStringLiteral("backup exited 0 without \"wrote %1: %2 drive(s)\"")
                           .arg(path)
                           .arg(asked.size());
    }
}

void FaultJudge::backupFailed(const CliRun& run, bool fileTouched, FaultCounts* c)
{
    gaveUp(QStringLiteral("backup"), run, c);
    if (!run.err.contains(QStringLiteral("nothing written"))) {
        ++c->unreported;
        c->findings << QStringLiteral("a failed backup did not say \"nothing written\"");
    }
    if (fileTouched) {
        ++c->unreported;
        c->findings << QStringLiteral("a failed backup (exit %1) changed the file").arg(run.code);
    }
    // The matrix only ever gives the drives values their profiles allow: a backup that found
    // one it does not took another reply for the drive's (issue 28).
    // (Not one whose allowed values depend on a setting the backup could not read.)
    static const QRegularExpression outside(
        QStringLiteral("holds a value its profile does not allow[^\n]*is not allowed"));
    if (outside.match(run.err).hasMatch()) {
        ++c->backupDiffer;
        c->findings << QStringLiteral("a backup read a value the drive does not hold: %1")
                           .arg(run.reason().left(300));
    }
}

void FaultJudge::finalState(const QVector<Setting>& file, const Truth& truth, FaultCounts* c)
{
    for (const Setting& s : file) {
        const QVector<quint16> t = truth.value(MatrixSim::key(s.slave, s.name));
        if (t != s.registers) {
            ++c->wrongAfterRestore;
            c->findings << QStringLiteral("at the end drive %1 %2 holds %3, the backup %4")
                               .arg(s.slave)
                               .arg(s.name, registersText(t), registersText(s.registers));
        }
    }
}

void FaultJudge::restore(const QVector<Setting>& file, const Truth& after, const CliRun& run,
                         FaultCounts* c)
{
    const QJsonObject report = run.json();
    const bool noDrives = report.value(QStringLiteral("drives")).toArray().isEmpty();
    if (run.code != 0)
        gaveUp(QStringLiteral("restore"), run, c);
    for (const Setting& s : file) {
        const QVector<quint16> t = after.value(MatrixSim::key(s.slave, s.name));
        const QJsonObject drive = driveReport(report, s.slave);
        const QJsonObject item = itemOf(drive, s.name);
        const QString status = item.value(QStringLiteral("status")).toString();
        const QString outcome = drive.value(QStringLiteral("outcome")).toString();
        if (t == s.registers)
            continue;
        const QString where = QStringLiteral("restore: drive %1 %2 (file %3, drive %4)")
                                  .arg(s.slave)
                                  .arg(s.name, registersText(s.registers), registersText(t));
        if (status == QLatin1String("verified") || status == QLatin1String("unchanged")) {
            ++c->notVerified;
            ++c->unreported;
            c->findings << QStringLiteral("%1 reported %2").arg(where, status);
        } else if (run.code == 0) {
            ++c->unreported;
            c->findings << QStringLiteral("%1: exit 0 (status '%2')").arg(where, status);
        } else if (!status.isEmpty()) {
            // Named: failed, not attempted, not confirmed.
        } else if (!drive.isEmpty() && outcome != QLatin1String("done")) {
            // The drive is named as not read or not attempted: nothing of it was written.
        } else if (noDrives && !run.reason().isEmpty()) {
            // Stopped before any drive ("error: …; nothing written").
        } else {
            ++c->unreported;
            c->findings
                << QStringLiteral("%1: not named in the report (exit %2)").arg(where).arg(run.code);
        }
    }
    if (run.code == 0) {
        for (const QJsonValue& d : report.value(QStringLiteral("drives")).toArray()) {
            const QString outcome = d.toObject().value(QStringLiteral("outcome")).toString();
            if (outcome != QLatin1String("done")) {
                ++c->unreported;
                c->findings << QStringLiteral("restore exited 0 with drive %1 '%2'")
                                   .arg(d.toObject().value(QStringLiteral("slave")).toInt())
                                   .arg(outcome);
            }
        }
        if (noDrives) {
            ++c->unreported;
            c->findings << QStringLiteral("restore exited 0 without a report");
        }
    }
}

void FaultJudge::needlessWrites(const QVector<Setting>& file, const Truth& before,
                                const CliRun& run, FaultCounts* c)
{
    const QJsonObject report = run.json();
    for (const Setting& s : file) {
        if (before.value(MatrixSim::key(s.slave, s.name)) != s.registers)
            continue;
        const QJsonObject item = itemOf(driveReport(report, s.slave), s.name);
        if (item.value(QStringLiteral("status")).toString() != QLatin1String("verified"))
            continue;
        // Read as equal and written all the same: one write of its block (an SPno table)
        // with a setting that did differ. Only a write the tool thought needed is a misread.
        QVector<quint16> read;
        for (const QJsonValue& v : item.value(QStringLiteral("deviceRegisters")).toArray())
            read << quint16(v.toInt());
        if (read == s.registers)
            continue;
        ++c->needlessWrites;
        c->findings << QStringLiteral("restore: drive %1 %2 written, but it already held %3")
                           .arg(s.slave)
                           .arg(s.name, registersText(s.registers));
    }
}

void FaultJudge::compare(const QVector<Setting>& fileOfSlave, const Truth& truth, int slave,
                         const CliRun& run, FaultCounts* c)
{
    if (run.code != 0) {
        gaveUp(QStringLiteral("compare drive %1").arg(slave), run, c);
        return;
    }
    QStringList named;
    for (const QJsonValue& v : run.json().value(QStringLiteral("differences")).toArray()) {
        const QJsonObject d = v.toObject();
        const QString parameter = d.value(QStringLiteral("parameter")).toString();
        named << parameter;
        QVector<quint16> shown;
        for (const QJsonValue& r : d.value(QStringLiteral("bRegisters")).toArray())
            shown << quint16(r.toInt());
        const QVector<quint16> t = truth.value(MatrixSim::key(slave, parameter));
        QVector<quint16> inFile;
        for (const Setting& s : fileOfSlave) {
            if (s.name == parameter)
                inFile = s.registers;
        }
        if (t == inFile || shown != t) {
            ++c->falseDifferences;
            c->findings << QStringLiteral("compare drive %1 %2: shown %3 against file %4, the "
                                          "drive holds %5")
                               .arg(slave)
                               .arg(parameter, registersText(shown), registersText(inFile),
                                    registersText(t));
        }
    }
    if (!run.json().contains(QStringLiteral("differences"))) {
        ++c->unreported;
        c->findings << QStringLiteral("compare drive %1 exited 0 without a report").arg(slave);
    }
    for (const Setting& s : fileOfSlave) {
        if (truth.value(MatrixSim::key(slave, s.name)) != s.registers && !named.contains(s.name)) {
            ++c->unreported;
            c->findings << QStringLiteral("compare drive %1: %2 differs but was not shown")
                               .arg(slave)
                               .arg(s.name);
        }
    }
}

} // namespace opentop::faultmatrix
