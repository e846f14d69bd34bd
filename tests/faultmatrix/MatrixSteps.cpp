#include "tests/faultmatrix/MatrixSteps.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

namespace opentop::faultmatrix {

namespace {

// Settings the matrix changes: ones a commissioning engineer changes, never the line's
// settings (machine number, baud) that would take the drive off the bus.
bool changeable(const Setting& s, quint16* low, quint16* high)
{
    static const QRegularExpression dbu(QStringLiteral("^spno[2-8]\\.(accel|decel|speed)$"));
    static const QRegularExpression dc(
        QStringLiteral("^(config\\.stall_time|preset\\.forward_speed|preset\\.reverse_speed|"
                       "pid\\.d_period)$"));
    if (s.registers.size() != 1)
        return false;
    if (dbu.match(s.name).hasMatch()) {
        const bool speed = s.name.endsWith(QLatin1String("speed"));
        *low = speed ? 300 : 1;
        *high = speed ? 2500 : 100;
        return true;
    }
    if (dc.match(s.name).hasMatch()) {
        *low = 10;
        *high = 200;
        return true;
    }
    return false;
}

} // namespace

MatrixSteps::MatrixSteps(const MatrixOptions& options, int seed, QTextStream& log)
    : m_options(options)
    , m_seed(seed)
    , m_log(log)
    , m_link(m_dir.filePath(QStringLiteral("ttyFM")))
    , m_file(m_dir.filePath(QStringLiteral("bus.json")))
    , m_sim(options.binDir)
    , m_cli(options.binDir, m_link, MatrixOptions::variantList(options.drives),
            options.drives == 1 ? QStringLiteral("1") : QStringLiteral("1-%1").arg(options.drives),
            options.baud)
    , m_random(std::mt19937::result_type(seed))
{
    m_counts.label = QStringLiteral("seed %1").arg(seed);
    m_cli.setTrace(!options.traceDir.isEmpty());
}

bool MatrixSteps::start(QString* error)
{
    if (!m_dir.isValid()) {
        *error = QStringLiteral("no temporary directory");
        return false;
    }
    return m_sim.start(MatrixOptions::deviceSpec(m_options.drives), m_options.faults, m_seed,
                       m_link, m_options.baud, error);
}

QVector<int> MatrixSteps::slaves() const
{
    QVector<int> ids;
    for (int i = 1; i <= m_options.drives; ++i)
        ids << i;
    return ids;
}

QString MatrixSteps::slaveList() const
{
    return m_options.drives == 1 ? QStringLiteral("1")
                                 : QStringLiteral("1-%1").arg(m_options.drives);
}

void MatrixSteps::note(const QString& text)
{
    m_log << QStringLiteral("  [%1] %2\n").arg(m_counts.label, text);
    m_log.flush();
}

void MatrixSteps::ran(const CliRun& run)
{
    ++m_counts.operations;
    if (m_options.verbose)
        m_log << MatrixCli::describe(run) << '\n';
    if (!m_options.traceDir.isEmpty()) {
        QFile file(QStringLiteral("%1/seed%2-%3-%4.log")
                       .arg(m_options.traceDir)
                       .arg(m_seed)
                       .arg(m_counts.operations, 2, 10, QLatin1Char('0'))
                       .arg(run.arguments.value(run.arguments.indexOf(QStringLiteral("--json")) + 1,
                                                run.arguments.value(6))));
        if (file.open(QIODevice::WriteOnly))
            file.write((MatrixCli::describe(run) + run.err).toUtf8());
    }
}

void MatrixSteps::abandon(const QString& step)
{
    ++m_counts.unreported; // not a silent failure, but a seed that proves nothing: fail
    m_counts.findings << QStringLiteral("%1 gave up %2 times in a row: seed abandoned")
                             .arg(step)
                             .arg(m_options.attempts);
    note(m_counts.findings.last());
}

Truth MatrixSteps::truth()
{
    QString error;
    const Truth t = m_sim.truth(m_backup, &error);
    if (!error.isEmpty()) {
        ++m_counts.unreported;
        m_counts.findings << QStringLiteral("cannot read the drives' truth: %1").arg(error);
    }
    return t;
}

bool MatrixSteps::backup()
{
    for (int attempt = 1; attempt <= m_options.attempts; ++attempt) {
        const bool existed = QFileInfo::exists(m_file);
        const QDateTime before = QFileInfo(m_file).lastModified();
        const CliRun run =
            m_cli.run({QStringLiteral("backup"), slaveList(), QStringLiteral("-o"), m_file});
        ran(run);
        if (run.code != 0) {
            const bool touched = QFileInfo::exists(m_file) != existed ||
                                 (existed && QFileInfo(m_file).lastModified() != before);
            FaultJudge::backupFailed(run, touched, &m_counts);
            note(QStringLiteral("backup gave up: %1").arg(m_counts.gaveUpReasons.last()));
            continue;
        }
        QString error;
        m_backup = BackupValues::load(m_file, &error);
        if (m_backup.isEmpty()) {
            ++m_counts.unreported;
            m_counts.findings << QStringLiteral("backup exited 0 but: %1").arg(error);
            return false;
        }
        FaultJudge::backupDone(m_backup, truth(), slaves(), m_file, run, &m_counts);
        note(QStringLiteral("backup: %1 values of %2 drives in %3 ms")
                 .arg(m_backup.size())
                 .arg(m_options.drives)
                 .arg(run.ms));
        return true;
    }
    abandon(QStringLiteral("backup"));
    return false;
}

int MatrixSteps::changeSettings()
{
    int changed = 0;
    for (int slave : slaves()) {
        QVector<Setting> candidates;
        for (const Setting& s : BackupValues::ofSlave(m_backup, slave)) {
            quint16 low = 0;
            quint16 high = 0;
            if (changeable(s, &low, &high))
                candidates << s;
        }
        std::shuffle(candidates.begin(), candidates.end(), m_random);
        const int n = std::min(int(candidates.size()), 1 + int(m_random() % 4));
        for (int i = 0; i < n; ++i) {
            const Setting& s = candidates.at(i);
            quint16 low = 0;
            quint16 high = 0;
            changeable(s, &low, &high);
            quint16 value = s.registers.first();
            while (value == s.registers.first())
                value = quint16(low + m_random() % (high - low + 1));
            if (m_sim.set(slave, s.address, value))
                ++changed;
            else
                m_counts.findings << QStringLiteral("the simulator refused to change drive %1 %2")
                                         .arg(slave)
                                         .arg(s.name);
        }
    }
    m_counts.settingsChanged += changed;
    note(QStringLiteral("%1 settings changed on the drives").arg(changed));
    return changed;
}

bool MatrixSteps::restore()
{
    for (int attempt = 1; attempt <= m_options.attempts; ++attempt) {
        const Truth before = truth();
        const CliRun run = m_cli.run(
            {QStringLiteral("--json"), QStringLiteral("restore"), m_file, QStringLiteral("--yes")});
        ran(run);
        FaultJudge::restore(m_backup, truth(), run, &m_counts);
        FaultJudge::needlessWrites(m_backup, before, run, &m_counts);
        if (run.code == 0) {
            note(QStringLiteral("restore: exit 0 in %1 ms").arg(run.ms));
            return true;
        }
        note(QStringLiteral("restore gave up: %1").arg(m_counts.gaveUpReasons.last()));
    }
    abandon(QStringLiteral("restore"));
    return false;
}

void MatrixSteps::sabotage()
{
    for (const Setting& s : m_backup) {
        quint16 low = 0;
        quint16 high = 0;
        if (changeable(s, &low, &high)) {
            m_sim.set(s.slave, s.address, quint16(s.registers.first() == low ? high : low));
            note(QStringLiteral("sabotage: drive %1 %2 changed behind the tool's back")
                     .arg(s.slave)
                     .arg(s.name));
            return;
        }
    }
}

bool MatrixSteps::compare()
{
    const Truth t = truth();
    for (int slave : slaves()) {
        bool done = false;
        for (int attempt = 1; attempt <= m_options.attempts && !done; ++attempt) {
            const CliRun run =
                m_cli.run({QStringLiteral("--json"), QStringLiteral("compare"),
                           QStringLiteral("%1:%2").arg(m_file).arg(slave), QString::number(slave)});
            ran(run);
            FaultJudge::compare(BackupValues::ofSlave(m_backup, slave), t, slave, run, &m_counts);
            done = run.code == 0;
            if (!done)
                note(QStringLiteral("compare gave up: %1").arg(m_counts.gaveUpReasons.last()));
        }
        if (!done) {
            abandon(QStringLiteral("compare drive %1").arg(slave));
            return false;
        }
    }
    note(QStringLiteral("compare: %1 drives").arg(m_options.drives));
    return true;
}

FaultCounts MatrixSteps::runSeed()
{
    QElapsedTimer timer;
    timer.start();
    QString error;
    if (!start(&error)) {
        ++m_counts.unreported;
        m_counts.findings << QStringLiteral("cannot start opentop-sim: %1").arg(error);
        return m_counts;
    }
    if (backup()) {
        changeSettings();
        if (restore()) {
            if (m_options.sabotage)
                sabotage();
            compare();
            // The drives once more, after everything: still equal to the backup.
            FaultJudge::finalState(m_backup, truth(), &m_counts);
        }
    }
    m_sim.stop();
    m_counts.ms = timer.elapsed();
    return m_counts;
}

} // namespace opentop::faultmatrix
