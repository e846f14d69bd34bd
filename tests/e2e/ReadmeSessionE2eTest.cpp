// The README's command-line session, run as it is shown: the simulator on a pty, then every
// command of the console block through the real opentop-cli, stdout and stderr as a terminal
// interleaves them. The program's output must be the README's, line by line; only timings
// ("293 ms", "8.3 s") and dates may differ. When they disagree, the test prints the session as
// the program gives it, ready to paste into the README.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>

using namespace opentop::test;

namespace {

const QString kReadmePort = QStringLiteral("/tmp/opentop-bus");

struct Step
{
    QString command; // as shown after "$ "
    QStringList expected;
};

// The console block after "A session against simulated drives on a pty".
QVector<Step> readmeSession(QString* error)
{
    QFile file(QStringLiteral(OPENTOP_SOURCE_DIR "/README.md"));
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot read README.md");
        return {};
    }
    const QString text = QString::fromUtf8(file.readAll());
    const qsizetype intro =
        text.indexOf(QStringLiteral("A session against simulated drives on a pty"));
    const qsizetype begin = text.indexOf(QStringLiteral("```console\n"), intro);
    const qsizetype end = text.indexOf(QStringLiteral("\n```"), begin + 11);
    if (intro < 0 || begin < 0 || end < 0) {
        *error = QStringLiteral("no console block after \"A session against simulated drives\"");
        return {};
    }
    QVector<Step> steps;
    for (const QString& line : text.mid(begin + 11, end - begin - 11).split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1String("$ ")))
            steps.append({line.mid(2), {}});
        else if (!steps.isEmpty())
            steps.last().expected << line;
    }
    return steps;
}

// Timings and dates vary from run to run; everything else must be the same.
QString normalised(QString line)
{
    static const QRegularExpression timing(QStringLiteral("\\b\\d+(\\.\\d+)? (ms|s)\\b"));
    static const QRegularExpression date(QStringLiteral("\\d{4}-\\d\\d-\\d\\d \\d\\d:\\d\\d"));
    line.replace(timing, QStringLiteral("# \\2"));
    line.replace(date, QStringLiteral("DATE"));
    while (line.endsWith(QLatin1Char(' ')))
        line.chop(1);
    return line;
}

// Lines a terminal session does not keep or that depend on the machine's load: the scan's
// progress (a terminal overwrites it in place) and the note on drives that answered late.
bool transient(const QString& line)
{
    static const QRegularExpression progress(QStringLiteral("^scan: \\d+ % "));
    return progress.match(line).hasMatch() ||
           line.contains(QLatin1String("answered only after the"));
}

// The program's output as a terminal shows it; with `stderrOnly` (a command ending in
// ">/dev/null") only what it writes to standard error.
QStringList runMerged(const QStringList& args, bool stderrOnly)
{
    QProcess p;
    if (stderrOnly)
        p.setStandardOutputFile(QProcess::nullDevice());
    p.setProcessChannelMode(stderrOnly ? QProcess::SeparateChannels : QProcess::MergedChannels);
    p.start(cliProgram(), args);
    if (!p.waitForStarted(5000) || !p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished(2000);
        return {QStringLiteral("<did not finish>")};
    }
    QStringList lines = QString::fromUtf8(stderrOnly ? p.readAllStandardError() : p.readAll())
                            .split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.last().isEmpty())
        lines.removeLast();
    return lines;
}

} // namespace

TEST(ReadmeSessionE2e, TheProgramSaysWhatTheReadmeShows)
{
    QString error;
    const QVector<Step> steps = readmeSession(&error);
    ASSERT_FALSE(steps.isEmpty()) << qPrintable(error);
    // The first command starts the simulator: the same devices, on a pty of this test's own.
    const QStringList simArgs = QProcess::splitCommand(steps.first().command);
    ASSERT_TRUE(simArgs.first().endsWith(QLatin1String("opentop-sim")))
        << qPrintable(steps.first().command);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString port = dir.filePath(QStringLiteral("opentop-bus"));
    QStringList args;
    for (int k = 1; k < simArgs.size(); ++k) {
        if (simArgs[k] == QLatin1String("&"))
            continue;
        args << (simArgs[k] == kReadmePort ? port : simArgs[k]);
    }
    SimProcess sim;
    ASSERT_TRUE(sim.start(args, &error)) << qPrintable(error);

    QHash<QString, QStringList> aliases;
    QString shown;    // the session as the program gives it
    QStringList diff; // the first lines that differ, per command
    for (const Step& step : steps.mid(1)) {
        shown += QStringLiteral("$ ") + step.command + QLatin1Char('\n');
        static const QRegularExpression alias(QStringLiteral("^alias (\\w+)='(.*)'$"));
        if (const QRegularExpressionMatch m = alias.match(step.command); m.hasMatch()) {
            aliases.insert(m.captured(1), QProcess::splitCommand(m.captured(2)));
            continue;
        }
        QStringList output;
        for (QString part : step.command.split(QStringLiteral("; "))) {
            const bool discard = part.endsWith(QLatin1String(" >/dev/null"));
            if (discard)
                part.chop(QStringLiteral(" >/dev/null").size());
            QStringList words = QProcess::splitCommand(part);
            if (aliases.contains(words.first()))
                words = aliases.value(words.first()) + words.mid(1);
            EXPECT_EQ(words.first(), QStringLiteral("opentop-cli")) << qPrintable(part);
            for (QString& w : words)
                w.replace(kReadmePort, port);
            output += runMerged(words.mid(1), discard);
        }
        for (QString& line : output)
            line.replace(port, kReadmePort);
        output.removeIf(transient);
        for (const QString& line : output)
            shown += line + QLatin1Char('\n');
        const qsizetype n = std::max(output.size(), step.expected.size());
        for (qsizetype k = 0; k < n; ++k) {
            const QString got =
                k < output.size() ? normalised(output[k]) : QStringLiteral("<none>");
            const QString want =
                k < step.expected.size() ? normalised(step.expected[k]) : QStringLiteral("<none>");
            if (got != want) {
                diff << QStringLiteral("$ %1\n  README:  %2\n  program: %3")
                            .arg(step.command, want, got);
                break;
            }
        }
    }
    sim.terminate();
    EXPECT_TRUE(diff.isEmpty()) << qPrintable(diff.join(QLatin1Char('\n')))
                                << "\n\nThe session as the program gives it:\n"
                                << qPrintable(shown);
}
