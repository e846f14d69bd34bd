// opentop-bench: performance figures of the real programs and stack against opentop-sim with
// wire timing on a pty, with ratios to references (a plain libmodbus loop, the wire's limit,
// peers) and the goals they are judged by (docs/performance.md). Composition only: the
// benchmarks live in bench/.
//
// Exit status: 0 every goal met, 1 a benchmark could not measure, 3 a goal was missed,
// 2 a usage error.
#include "bench/BenchReport.h"
#include "bench/BusBackupBenchmark.h"
#include "bench/EolBenchmark.h"
#include "bench/GuiBenchmark.h"
#include "bench/MachineInfo.h"
#include "bench/PollBenchmark.h"
#include "bench/ScanBenchmark.h"
#include "bench/StartupBenchmark.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTextStream>
#include <memory>
#include <vector>

using namespace opentop;

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("opentop-bench"));
    QTextStream out(stdout);
    QTextStream err(stderr);

    std::vector<std::unique_ptr<Benchmark>> all;
    all.push_back(std::make_unique<PollBenchmark>());
    all.push_back(std::make_unique<ScanBenchmark>());
    all.push_back(std::make_unique<BusBackupBenchmark>());
    all.push_back(std::make_unique<GuiBenchmark>());
    all.push_back(std::make_unique<StartupBenchmark>());
    all.push_back(std::make_unique<EolBenchmark>());

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Performance figures of OpenTOP against opentop-sim with wire timing on a pty, with "
        "ratios and goals (docs/performance.md). Exit status: 0 every goal met, 1 a benchmark "
        "could not measure, 3 a goal was missed."));
    parser.addHelpOption();
    parser.addOptions({
        {QStringLiteral("list"), QStringLiteral("List the benchmarks and exit.")},
        {QStringLiteral("seconds"),
         QStringLiteral("Measuring time per throughput figure (default 3)."), QStringLiteral("S"),
         QStringLiteral("3")},
        {QStringLiteral("gui-seconds"),
         QStringLiteral("Measuring time per GUI load case after a 65 s warm-up that fills the "
                        "trends (default 30)."),
         QStringLiteral("S"), QStringLiteral("30")},
    });
    parser.addPositionalArgument(QStringLiteral("NAME"),
                                 QStringLiteral("Benchmarks to run "
                                                "(default all)."),
                                 QStringLiteral("[NAME...]"));
    parser.process(app);

    if (parser.isSet(QStringLiteral("list"))) {
        for (const auto& b : all)
            out << b->name().leftJustified(12) << b->description() << '\n';
        return 0;
    }
    QStringList names = parser.positionalArguments();
    for (const QString& name : names) {
        if (std::none_of(all.begin(), all.end(),
                         [&](const auto& b) { return b->name() == name; })) {
            err << QStringLiteral("opentop-bench: unknown benchmark %1; see --list").arg(name)
                << Qt::endl;
            return 2;
        }
    }
    BenchEnvironment env;
    env.binDir = QCoreApplication::applicationDirPath();
    bool ok = false;
    env.seconds = parser.value(QStringLiteral("seconds")).toDouble(&ok);
    bool guiOk = false;
    env.guiSeconds = parser.value(QStringLiteral("gui-seconds")).toDouble(&guiOk);
    if (!ok || !guiOk || env.seconds < 0.5 || env.guiSeconds < 5) {
        err << QStringLiteral("opentop-bench: --seconds needs at least 0.5, --gui-seconds at "
                              "least 5")
            << Qt::endl;
        return 2;
    }

    BenchReport report(out);
    report.note(QStringLiteral("machine: %1").arg(MachineInfo::describe()));
    for (const auto& b : all) {
        if (!names.isEmpty() && !names.contains(b->name()))
            continue;
        QElapsedTimer timer;
        timer.start();
        QString error;
        if (!b->run(env, report, &error))
            report.failed(b->name(), error);
        report.note(
            QStringLiteral("%1 took %2 s").arg(b->name()).arg(timer.elapsed() / 1000.0, 0, 'f', 1));
    }
    report.printSummary();
    if (!report.failures().isEmpty())
        return 1;
    return report.missedGoals().isEmpty() ? 0 : 3;
}
