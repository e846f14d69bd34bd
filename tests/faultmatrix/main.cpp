// opentop-faultmatrix: the fault matrix over a real line (issue 11, section 3). Drives the
// real opentop-sim (--wire-timing, seeded faults, a pty) and opentop-cli as a user would, and
// counts what the tool got wrong or did not report. See docs/communication.md.
#include "tests/faultmatrix/FaultCounts.h"
#include "tests/faultmatrix/LateSweep.h"
#include "tests/faultmatrix/MatrixOptions.h"
#include "tests/faultmatrix/MatrixSteps.h"
#include "tests/faultmatrix/SelfTest.h"
#include "tests/faultmatrix/VanishScenario.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <cstdio>

using namespace opentop::faultmatrix;

namespace {

void printTable(QTextStream& out, const QVector<FaultCounts>& rows)
{
    FaultCounts total;
    total.label = QStringLiteral("total");
    FaultCounts::printHeader(out);
    for (const FaultCounts& row : rows) {
        row.printRow(out);
        total.add(row);
    }
    total.printRow(out);
    out << "must be 0: backup≠drive, not-verified, wrong-after, unreported, false-diffs, "
           "needless-writes\n";
    if (!total.gaveUpReasons.isEmpty()) {
        out << "operations that gave up, with the reason the tool gave:\n";
        for (const FaultCounts& row : rows) {
            for (const QString& r : row.gaveUpReasons)
                out << "  " << row.label << ": " << r << '\n';
        }
    }
    if (!total.findings.isEmpty()) {
        out << "FINDINGS:\n";
        for (const FaultCounts& row : rows) {
            for (const QString& f : row.findings)
                out << "  " << row.label << ": " << f << '\n';
        }
    }
    out << (total.clean() ? "RESULT: clean\n" : "RESULT: NOT CLEAN\n");
    out.flush();
}

} // namespace

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    QString error;
    const std::optional<MatrixOptions> options =
        MatrixOptions::parse(QCoreApplication::arguments().mid(1), &error);
    if (!options) {
        if (!error.isEmpty())
            std::fprintf(stderr, "opentop-faultmatrix: %s\n", qPrintable(error));
        out << MatrixOptions::usage();
        return error.isEmpty() ? 0 : 2;
    }
    if (options->selfTest)
        return SelfTest(*options, out).run();
    if (!options->lateSweepMs.isEmpty())
        return LateSweep(*options, out).run() ? 0 : 1;

    QElapsedTimer timer;
    timer.start();
    out << QStringLiteral("fault matrix: %1 drives (%2), faults %3, seeds %4%5\n")
               .arg(options->drives)
               .arg(MatrixOptions::deviceSpec(std::min(options->drives, 4)) +
                    (options->drives > 4 ? QStringLiteral(",…") : QString()))
               .arg(options->faults)
               .arg([&] {
                   QStringList s;
                   for (int seed : options->seeds)
                       s << QString::number(seed);
                   return s.join(QLatin1Char(','));
               }())
               .arg(options->vanish ? QStringLiteral(", with the port vanishing") : QString());
    out.flush();
    QVector<FaultCounts> rows;
    for (int seed : options->seeds) {
        MatrixSteps steps(*options, seed, out);
        rows << steps.runSeed();
        if (options->vanish)
            rows << VanishScenario(*options, seed, out).run();
    }
    printTable(out, rows);
    out << QStringLiteral("wall time %1 s\n").arg(double(timer.elapsed()) / 1000.0, 0, 'f', 1);
    out.flush();
    bool clean = true;
    for (const FaultCounts& row : rows)
        clean = clean && row.clean();
    return clean ? 0 : 1;
}
