// `opentop-cli monitor` losing its port (issue 28, item 6): the simulator behind the pty link
// stops, the monitor says "link lost" once and nothing more while it is lost, then comes back
// by itself when a simulator is started again on the same link, with the gap marked in its CSV;
// with --give-up it ends with exit 1 instead. Real processes, exit codes, stderr and the file.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QThread>
#include <csignal>
#include <functional>
#include <memory>

using namespace opentop::test;

namespace {

constexpr int kIntervalMs = 200;

// The simulator on the pty symlink `link`. Stopped with SIGTERM, it removes the link, as a USB
// adapter pulled out takes its /dev/ttyUSB0 with it (a SIGKILLed one would leave the link to a
// pts number another program may be given next).
std::unique_ptr<SimProcess> startSim(const QString& link)
{
    auto sim = std::make_unique<SimProcess>();
    QString error;
    const bool ok = sim->start(
        {QStringLiteral("--devices"), QStringLiteral("dbu200@1"), QStringLiteral("--pty"), link},
        &error);
    EXPECT_TRUE(ok) << error.toStdString();
    if (!ok)
        return nullptr;
    return sim;
}

// opentop-cli --port LINK monitor 1 --interval 200 EXTRA...
void startMonitor(QProcess& cli, const QString& link, const QStringList& extra)
{
    cli.start(cliProgram(), QStringList{QStringLiteral("--port"), link, QStringLiteral("--variant"),
                                        QStringLiteral("1=dbu200"), QStringLiteral("monitor"),
                                        QStringLiteral("1"), QStringLiteral("--interval"),
                                        QString::number(kIntervalMs)} +
                                extra);
}

// What the monitor printed so far, read as it comes.
struct Streams
{
    QString out;
    QString err;

    void read(QProcess& p, int waitMs)
    {
        p.waitForReadyRead(waitMs);
        out += QString::fromUtf8(p.readAllStandardOutput());
        err += QString::fromUtf8(p.readAllStandardError());
    }
    // Reads until `done` or `timeoutMs`; returns done().
    bool readUntil(QProcess& p, const std::function<bool()>& done, int timeoutMs)
    {
        QElapsedTimer timer;
        timer.start();
        while (!done() && timer.elapsed() < timeoutMs && p.state() == QProcess::Running)
            read(p, 50);
        read(p, 0);
        return done();
    }
    // Reads for `ms` whatever comes.
    void readFor(QProcess& p, int ms)
    {
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < ms)
            read(p, 50);
    }
    int outLines() const { return int(out.count(QLatin1Char('\n'))); }
};

// One CSV line's cells (quoted cells may hold commas).
QStringList csvCells(const QString& line)
{
    QStringList cells{QString()};
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line.at(i);
        if (quoted && c == QLatin1Char('"') && i + 1 < line.size() &&
            line.at(i + 1) == QLatin1Char('"')) {
            cells.last() += c;
            ++i;
        } else if (c == QLatin1Char('"')) {
            quoted = !quoted;
        } else if (c == QLatin1Char(',') && !quoted) {
            cells << QString();
        } else {
            cells.last() += c;
        }
    }
    return cells;
}

// The line a poll that failed prints ("TIME error: machine number 1: ...").
const QRegularExpression kPollError(QStringLiteral("^\\S+ error: "),
                                    QRegularExpression::MultilineOption);

const QRegularExpression kIsoTime(
    QStringLiteral("^\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d\\.\\d{3}(Z|[+-]\\d\\d:\\d\\d)$"));

} // namespace

TEST(CliMonitorLinkE2e, ALostLinkIsSaidOnceAndMonitoringGoesOnWhenThePortIsBack)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyMONITOR"));
    const QString csvPath = dir.filePath(QStringLiteral("monitor.csv"));
    std::unique_ptr<SimProcess> sim = startSim(link);
    ASSERT_TRUE(sim);
    QProcess cli;
    startMonitor(cli, link, {QStringLiteral("--csv"), csvPath});
    ASSERT_TRUE(cli.waitForStarted(5000));
    Streams s;
    ASSERT_TRUE(s.readUntil(
        cli, [&] { return s.outLines() >= 3; }, 10000)) // header, 2 samples
        << (s.out + s.err).toStdString();

    // The simulator goes: said once, with the time and the port.
    EXPECT_EQ(sim->terminate(), 0);
    sim.reset();
    ASSERT_TRUE(s.readUntil(
        cli, [&] { return s.err.contains(QStringLiteral("link lost")); }, 5000))
        << s.err.toStdString();
    const int outAtLoss = s.outLines();
    s.readFor(cli, 10 * kIntervalMs); // ten intervals without the port
    EXPECT_EQ(s.err.count(QStringLiteral("lost")), 1) << s.err.toStdString();
    EXPECT_FALSE(s.err.contains(QStringLiteral("is not open"))) << s.err.toStdString();
    EXPECT_FALSE(kPollError.match(s.err).hasMatch()) << s.err.toStdString();
    EXPECT_LE(s.outLines(), outAtLoss + 1) << "no sample lines while lost: " << s.out.toStdString();
    const QRegularExpressionMatch lost =
        QRegularExpression(QStringLiteral("(?:^|\\n)(\\S+) link lost: %1 \\(")
                               .arg(QRegularExpression::escape(link)))
            .match(s.err);
    ASSERT_TRUE(lost.hasMatch()) << s.err.toStdString();
    EXPECT_TRUE(kIsoTime.match(lost.captured(1)).hasMatch()) << lost.captured(1).toStdString();
    EXPECT_EQ(cli.state(), QProcess::Running) << "it waits for the port";

    // A simulator on the same link again: the monitor finds it by itself and samples go on.
    sim = startSim(link);
    ASSERT_TRUE(sim);
    ASSERT_TRUE(s.readUntil(
        cli, [&] { return s.err.contains(QStringLiteral("link back after")); }, 10000))
        << s.err.toStdString();
    const QRegularExpressionMatch back =
        QRegularExpression(QStringLiteral("link back after (\\d+\\.\\d) s: %1")
                               .arg(QRegularExpression::escape(link)))
            .match(s.err);
    ASSERT_TRUE(back.hasMatch()) << s.err.toStdString();
    EXPECT_GE(back.captured(1).toDouble(), 2.0); // the ten intervals at least
    EXPECT_LT(back.captured(1).toDouble(), 15.0);
    const int outAtBack = s.outLines();
    ASSERT_TRUE(s.readUntil(
        cli, [&] { return s.outLines() >= outAtBack + 2; }, 5000))
        << s.out.toStdString();
    ::kill(pid_t(cli.processId()), SIGINT);
    ASSERT_TRUE(cli.waitForFinished(5000));
    s.read(cli, 0);
    EXPECT_EQ(cli.exitCode(), 130) << s.err.toStdString(); // Ctrl-C, as without a loss
    EXPECT_EQ(s.err.count(QStringLiteral("lost")), 1) << s.err.toStdString();
    EXPECT_EQ(s.err.count(QStringLiteral("link back")), 1) << s.err.toStdString();
    EXPECT_EQ(sim->terminate(), 0);

    // The CSV: samples, a "link lost" row, a "link back" row, samples again; the gap rows have
    // the time and the note only.
    QFile file(csvPath);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QStringList rows =
        QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_GE(rows.size(), 6) << rows.join(QLatin1Char('\n')).toStdString();
    const QStringList header = csvCells(rows.first());
    EXPECT_EQ(header.mid(0, 3), (QStringList{QStringLiteral("timestamp"), QStringLiteral("slave"),
                                             QStringLiteral("family")}));
    EXPECT_EQ(header.value(header.size() - 2), QStringLiteral("alarm"));
    EXPECT_EQ(header.last(), QStringLiteral("note"));
    int lostRow = -1;
    int backRow = -1;
    for (int i = 1; i < rows.size(); ++i) {
        const QStringList cells = csvCells(rows[i]);
        ASSERT_EQ(cells.size(), header.size()) << rows[i].toStdString();
        EXPECT_TRUE(kIsoTime.match(cells.first()).hasMatch()) << rows[i].toStdString();
        const QString note = cells.last();
        if (note.isEmpty()) {
            EXPECT_EQ(cells[1], QStringLiteral("1")) << rows[i].toStdString();
            EXPECT_EQ(cells[2], QStringLiteral("dbu")) << rows[i].toStdString();
            EXPECT_TRUE(lostRow < 0 || backRow >= 0) << "a sample inside the gap: " << i;
            continue;
        }
        EXPECT_TRUE(note == QLatin1String("link lost") || note == QLatin1String("link back"))
            << rows[i].toStdString();
        EXPECT_EQ(note == QLatin1String("link lost") ? lostRow : backRow, -1) << "one each";
        (note == QLatin1String("link lost") ? lostRow : backRow) = i;
        for (int c = 1; c + 1 < cells.size(); ++c)
            EXPECT_TRUE(cells[c].isEmpty()) << "cell " << c << " of " << rows[i].toStdString();
    }
    EXPECT_GE(lostRow, 3) << "samples before the gap";
    EXPECT_EQ(backRow, lostRow + 1);
    EXPECT_GE(rows.size() - backRow - 1, 2) << "samples after the gap";
}

TEST(CliMonitorLinkE2e, GiveUpEndsWithExit1WhenTheLinkStaysLost)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyGIVEUP"));
    std::unique_ptr<SimProcess> sim = startSim(link);
    ASSERT_TRUE(sim);
    QProcess cli;
    startMonitor(cli, link, {QStringLiteral("--give-up"), QStringLiteral("2")});
    ASSERT_TRUE(cli.waitForStarted(5000));
    Streams s;
    ASSERT_TRUE(s.readUntil(
        cli, [&] { return s.outLines() >= 3; }, 10000))
        << (s.out + s.err).toStdString();

    EXPECT_EQ(sim->terminate(), 0);
    QElapsedTimer sinceLoss;
    sinceLoss.start();
    ASSERT_TRUE(cli.waitForFinished(8000)) << "still monitoring a lost link";
    const qint64 elapsed = sinceLoss.elapsed();
    s.read(cli, 0);
    EXPECT_EQ(cli.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(cli.exitCode(), 1) << s.err.toStdString(); // a communication failure
    EXPECT_GE(elapsed, 1900) << "gave up before its 2 s";
    EXPECT_LT(elapsed, 5000);
    EXPECT_EQ(s.err.count(QStringLiteral("link lost: %1").arg(link)), 1) << s.err.toStdString();
    EXPECT_TRUE(s.err.contains(QStringLiteral("error: the link to %1 was lost at ").arg(link)))
        << s.err.toStdString();
    EXPECT_TRUE(s.err.contains(QStringLiteral("(--give-up 2)"))) << s.err.toStdString();
    EXPECT_TRUE(s.err.contains(QStringLiteral("monitoring stopped"))) << s.err.toStdString();
    EXPECT_FALSE(s.err.contains(QStringLiteral("is not open"))) << s.err.toStdString();
    int errors = 0;
    for (const QString& line : s.err.split(QLatin1Char('\n')))
        errors += line.startsWith(QLatin1String("error:"));
    EXPECT_EQ(errors, 1) << s.err.toStdString();
}
