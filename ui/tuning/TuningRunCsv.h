#pragma once

#include <QCoreApplication>
#include <QString>

namespace opentop {

struct TuningRun;

// A run as CSV: header lines starting with '#' (drive, test, gains, metrics with their units),
// then one line per sample: t_ms, command, speed, current_A, output. Numbers in C locale.
class TuningRunCsv
{
    Q_DECLARE_TR_FUNCTIONS(opentop::TuningRunCsv)
public:
    static QString text(const TuningRun& run, const QString& drive);
    static bool write(const QString& path, const TuningRun& run, const QString& drive,
                      QString* error);
};

} // namespace opentop
