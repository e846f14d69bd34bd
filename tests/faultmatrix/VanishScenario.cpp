#include "tests/faultmatrix/VanishScenario.h"

#include "tests/faultmatrix/MatrixSteps.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QRegularExpression>

namespace opentop::faultmatrix {

VanishScenario::VanishScenario(const MatrixOptions& options, int seed, QTextStream& log)
    : m_options(options)
    , m_seed(seed)
    , m_log(log)
{
}

int VanishScenario::requestsIn(const QString& trace, const QList<int>& functions)
{
    // "12:37:25.739 TX #1 01 06 13 03 00 64 …": a request the tool sent.
    static const QRegularExpression request(
        QStringLiteral("\\bTX #\\d+ [0-9A-Fa-f]{2} ([0-9A-Fa-f]{2}) "));
    int n = 0;
    QRegularExpressionMatchIterator it = request.globalMatch(trace);
    while (it.hasNext()) {
        const int function = it.next().captured(1).toInt(nullptr, 16);
        n += functions.contains(function);
    }
    return n;
}

void VanishScenario::checkVanished(MatrixSteps& steps, const QString& what, const CliRun& run,
                                   bool pulled)
{
    FaultCounts& c = steps.counts();
    if (!pulled) {
        ++c.unreported;
        c.findings << QStringLiteral("%1 ended before the port was pulled out").arg(what);
        return;
    }
    if (run.code != 1) {
        ++c.unreported;
        c.findings << QStringLiteral("%1 without its port exited %2, not 1 (communication)")
                          .arg(what)
                          .arg(run.code);
    }
    const QString reason = run.reason();
    if (!reason.contains(QStringLiteral("port"), Qt::CaseInsensitive)) {
        ++c.unreported;
        c.findings
            << QStringLiteral("%1 without its port did not name the port: '%2'").arg(what, reason);
    }
    steps.note(QStringLiteral("%1 lost its port: exit %2: %3").arg(what).arg(run.code).arg(reason));
}

void VanishScenario::vanishingBackup(MatrixSteps& steps)
{
    const int pullAfter = std::max(1, m_options.drives * 13 / 3);
    bool pulled = false;
    const CliRun run = steps.cli().runWatching(
        {QStringLiteral("backup"), steps.slaveList(), QStringLiteral("-o"), steps.file()},
        [&](const QString& trace) {
            if (requestsIn(trace, {0x03, 0x04}) < pullAfter)
                return false;
            pulled = steps.sim().command(QStringLiteral("unplug")) == QLatin1String("unplugged");
            return true;
        });
    steps.ran(run);
    if (run.code != 0)
        FaultJudge::backupFailed(run, QFileInfo::exists(steps.file()), &steps.counts());
    checkVanished(steps, QStringLiteral("backup"), run, pulled);
    steps.sim().command(QStringLiteral("replug"));
}

void VanishScenario::vanishingRestore(MatrixSteps& steps, int changed)
{
    // Early: a restore that gives up on its own (a busy drive) must not end first.
    const int pullAfter = std::max(1, changed / 5);
    bool pulled = false;
    const CliRun run = steps.cli().runWatching(
        {QStringLiteral("--json"), QStringLiteral("restore"), steps.file(),
         QStringLiteral("--yes")},
        [&](const QString& trace) {
            if (requestsIn(trace, {0x06, 0x10}) < pullAfter)
                return false;
            pulled = steps.sim().command(QStringLiteral("unplug")) == QLatin1String("unplugged");
            return true;
        });
    steps.ran(run);
    // The report against the drives: every setting reported written is in the drive, every
    // one that is not is named.
    FaultJudge::restore(steps.backupSettings(), steps.truth(), run, &steps.counts());
    checkVanished(steps, QStringLiteral("restore"), run, pulled);
    const QJsonObject report = run.json();
    int verified = 0;
    int notConfirmed = 0;
    for (const QJsonValue& d : report.value(QStringLiteral("drives")).toArray()) {
        verified += d.toObject().value(QStringLiteral("verified")).toInt();
        notConfirmed += d.toObject().value(QStringLiteral("notConfirmed")).toInt();
    }
    steps.note(QStringLiteral("restore report: %1 written and verified, %2 not confirmed before "
                              "the port vanished")
                   .arg(verified)
                   .arg(notConfirmed));
    steps.sim().command(QStringLiteral("replug"));
}

FaultCounts VanishScenario::run()
{
    QElapsedTimer timer;
    timer.start();
    MatrixSteps steps(m_options, m_seed, m_log);
    steps.counts().label = QStringLiteral("vanish %1").arg(m_seed);
    QString error;
    if (!steps.start(&error)) {
        ++steps.counts().unreported;
        steps.counts().findings << QStringLiteral("cannot start opentop-sim: %1").arg(error);
        return steps.counts();
    }
    vanishingBackup(steps);
    if (steps.backup()) {
        const int changed = steps.changeSettings();
        vanishingRestore(steps, changed);
        if (steps.restore()) {
            steps.compare();
            FaultJudge::finalState(steps.backupSettings(), steps.truth(), &steps.counts());
        }
    }
    steps.sim().stop();
    steps.counts().ms = timer.elapsed();
    return steps.counts();
}

} // namespace opentop::faultmatrix
