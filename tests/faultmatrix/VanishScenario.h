#pragma once

#include "tests/faultmatrix/FaultCounts.h"
#include "tests/faultmatrix/MatrixCli.h"
#include "tests/faultmatrix/MatrixOptions.h"

#include <QTextStream>

namespace opentop::faultmatrix {

class MatrixSteps;

// The port pulled out under the tool (the simulator's console "unplug" closes the pty) in the
// middle of a backup and of a restore: a clear error and the documented exit code, a report
// that matches the drives exactly, and after "replug" a second run that completes.
class VanishScenario
{
public:
    VanishScenario(const MatrixOptions& options, int seed, QTextStream& log);
    FaultCounts run();

    // Requests (function `function`, e.g. 0x03 or 0x06) sent so far in an opentop-cli trace.
    static int requestsIn(const QString& trace, const QList<int>& functions);

private:
    void vanishingBackup(MatrixSteps& steps);
    void vanishingRestore(MatrixSteps& steps, int changed);
    // The run that lost its port: exit 1, a reason that names the port.
    void checkVanished(MatrixSteps& steps, const QString& what, const CliRun& run, bool pulled);

    const MatrixOptions& m_options;
    int m_seed;
    QTextStream& m_log;
};

} // namespace opentop::faultmatrix
