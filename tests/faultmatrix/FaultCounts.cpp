#include "tests/faultmatrix/FaultCounts.h"

namespace opentop::faultmatrix {

bool FaultCounts::clean() const
{
    return backupDiffer == 0 && notVerified == 0 && wrongAfterRestore == 0 && unreported == 0 &&
           falseDifferences == 0 && needlessWrites == 0;
}

void FaultCounts::add(const FaultCounts& o)
{
    backupValues += o.backupValues;
    backupDiffer += o.backupDiffer;
    settingsChanged += o.settingsChanged;
    notVerified += o.notVerified;
    wrongAfterRestore += o.wrongAfterRestore;
    unreported += o.unreported;
    falseDifferences += o.falseDifferences;
    needlessWrites += o.needlessWrites;
    gaveUp += o.gaveUp;
    operations += o.operations;
    ms += o.ms;
    gaveUpReasons += o.gaveUpReasons;
    findings += o.findings;
}

void FaultCounts::printHeader(QTextStream& out)
{
    out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10 %11 %12\n")
               .arg(QStringLiteral("run"), -10)
               .arg(QStringLiteral("values"), 7)
               .arg(QStringLiteral("backup≠drive"), 12)
               .arg(QStringLiteral("changed"), 7)
               .arg(QStringLiteral("not-verified"), 12)
               .arg(QStringLiteral("wrong-after"), 11)
               .arg(QStringLiteral("unreported"), 10)
               .arg(QStringLiteral("false-diffs"), 11)
               .arg(QStringLiteral("needless-writes"), 15)
               .arg(QStringLiteral("gave-up"), 7)
               .arg(QStringLiteral("cli-runs"), 8)
               .arg(QStringLiteral("time"), 7);
}

void FaultCounts::printRow(QTextStream& out) const
{
    out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10 %11 %12\n")
               .arg(label, -10)
               .arg(backupValues, 7)
               .arg(backupDiffer, 12)
               .arg(settingsChanged, 7)
               .arg(notVerified, 12)
               .arg(wrongAfterRestore, 11)
               .arg(unreported, 10)
               .arg(falseDifferences, 11)
               .arg(needlessWrites, 15)
               .arg(gaveUp, 7)
               .arg(operations, 8)
               .arg(QStringLiteral("%1 s").arg(double(ms) / 1000.0, 0, 'f', 1), 7);
}

} // namespace opentop::faultmatrix
