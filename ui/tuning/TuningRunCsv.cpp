#include "ui/tuning/TuningRunCsv.h"

#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"

#include "ui/tuning/TuningRun.h"

namespace opentop {

namespace {

QString number(double v, int decimals = 3)
{
    return QString::number(v, 'f', decimals);
}

} // namespace

QString TuningRunCsv::text(const TuningRun& run, const QString& drive)
{
    const TuningRunner::Result& r = run.result;
    const StepMetrics& m = r.metrics;
    const QString unit = r.speedUnit;
    QStringList lines;
    lines << QStringLiteral("# OpenTOP speed loop step test");
    // Names and messages on one comment line each, whatever they hold (DisplayText).
    lines << QStringLiteral("# drive: %1").arg(DisplayText::escaped(drive));
    lines << QStringLiteral("# run: %1%2")
                 .arg(DisplayText::escaped(run.title),
                      run.isPrediction() ? QStringLiteral(" (predicted)") : QString());
    lines << QStringLiteral("# step: %1 -> %2 %3").arg(number(r.from, 1), number(r.to, 1), unit);
    lines << QStringLiteral("# gains: P %1, I %2, D %3, D period %4 ms")
                 .arg(number(run.gains.p, 4), number(run.gains.i, 4), number(run.gains.d, 4))
                 .arg(run.gains.dPeriodMs);
    if (m.valid) {
        lines << QStringLiteral("# rise_time_ms: %1")
                     .arg(m.riseMs ? number(*m.riseMs, 1) : QStringLiteral("not reached"));
        lines << QStringLiteral("# overshoot_percent: %1").arg(number(m.overshootPercent, 2));
        lines << QStringLiteral("# settling_time_2pct_ms: %1")
                     .arg(m.settlingMs ? number(*m.settlingMs, 1) : QStringLiteral("not settled"));
        lines << QStringLiteral("# steady_state_error: %1 %2")
                     .arg(number(m.steadyStateError, 2), unit);
        lines << QStringLiteral("# peak_current_A: %1").arg(number(m.peakCurrent, 3));
    } else if (!r.error.isEmpty()) {
        lines << QStringLiteral("# error: %1").arg(DisplayText::escaped(r.error));
    }
    if (!r.stopDetail.isEmpty())
        lines << QStringLiteral("# stop: %1").arg(DisplayText::escaped(r.stopDetail));
    lines << QStringLiteral("t_ms,command_%1,speed_%1,current_A,output").arg(unit);
    for (const TuningSample& s : r.samples)
        lines << QStringLiteral("%1,%2,%3,%4,%5")
                     .arg(number(s.tMs, 2), number(s.command), number(s.speed), number(s.current),
                          number(s.output));
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

bool TuningRunCsv::write(const QString& path, const TuningRun& run, const QString& drive,
                         QString* error)
{
    return OutputFile::write(path, text(run, drive).toUtf8(), error);
}

} // namespace opentop
