#include "tests/faultmatrix/LateSweep.h"

#include "tests/faultmatrix/MatrixSteps.h"

namespace opentop::faultmatrix {

LateSweep::LateSweep(const MatrixOptions& options, QTextStream& out)
    : m_options(options)
    , m_out(out)
{
}

bool LateSweep::run()
{
    QVector<Row> rows;
    bool clean = true;
    int cellIndex = 0;
    for (int baud : m_options.sweepBauds) {
        for (int delayMs : m_options.lateSweepMs) {
            ++cellIndex;
            MatrixOptions cell = m_options;
            cell.baud = baud;
            cell.faults = QStringLiteral("late=%1,late_ms=%2").arg(m_options.lateRate).arg(delayMs);
            Row row{baud, delayMs, {}};
            row.counts.label = QStringLiteral("%1 bit/s, %2 ms late").arg(baud).arg(delayMs);
            for (int given : m_options.seeds) {
                // Each cell draws its own faults: seed 1 is 101, 102, ... across the cells.
                const int seed = given * 100 + cellIndex;
                MatrixSteps steps(cell, seed, m_out);
                FaultCounts counts = steps.runSeed();
                for (QString& f : counts.findings)
                    f = QStringLiteral("%1 seed %2: %3").arg(row.counts.label).arg(seed).arg(f);
                row.counts.add(counts);
            }
            clean = clean && row.counts.clean();
            rows << row;
        }
    }
    printTable(rows);
    return clean;
}

void LateSweep::printTable(const QVector<Row>& rows) const
{
    m_out << QStringLiteral("\nlate-reply sweep: %1 drives, %2 % of replies late, seeds %3\n")
                 .arg(m_options.drives)
                 .arg(m_options.lateRate * 100.0, 0, 'f', 0)
                 .arg(m_options.seeds.size());
    m_out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9\n")
                 .arg(QStringLiteral("rate"), 7)
                 .arg(QStringLiteral("delay"), 8)
                 .arg(QStringLiteral("values"), 7)
                 .arg(QStringLiteral("false-rows"), 10)
                 .arg(QStringLiteral("misreads"), 9)
                 .arg(QStringLiteral("needless-writes"), 15)
                 .arg(QStringLiteral("unreported"), 10)
                 .arg(QStringLiteral("gave-up"), 7)
                 .arg(QStringLiteral("time"), 8);
    FaultCounts total;
    for (const Row& r : rows) {
        const FaultCounts& c = r.counts;
        total.add(c);
        m_out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9\n")
                     .arg(r.baud, 7)
                     .arg(QStringLiteral("%1 ms").arg(r.delayMs), 8)
                     .arg(c.backupValues, 7)
                     .arg(c.falseDifferences, 10)
                     .arg(c.misreads(), 9)
                     .arg(c.needlessWrites, 15)
                     .arg(c.unreported, 10)
                     .arg(c.gaveUp, 7)
                     .arg(QStringLiteral("%1 s").arg(double(c.ms) / 1000.0, 0, 'f', 1), 8);
    }
    m_out << QStringLiteral("must be 0: false-rows, misreads, needless-writes, unreported\n");
    if (!total.findings.isEmpty()) {
        m_out << "FINDINGS:\n";
        for (const QString& f : total.findings)
            m_out << "  " << f << '\n';
    }
    m_out << (total.clean() ? "RESULT: clean\n" : "RESULT: NOT CLEAN\n");
    m_out.flush();
}

} // namespace opentop::faultmatrix
