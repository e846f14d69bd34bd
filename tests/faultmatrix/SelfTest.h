#pragma once

#include "tests/faultmatrix/MatrixOptions.h"

#include <QTextStream>

namespace opentop::faultmatrix {

// Proves the matrix can fail: the counting rules fed made-up reports with planted faults
// (each must be counted, a clean one must not), then a short run with --sabotage (a drive
// changed behind the tool's back after the restore) that must end not clean.
class SelfTest
{
public:
    SelfTest(const MatrixOptions& options, QTextStream& log);
    // 0 when every planted fault was caught.
    int run();

private:
    bool check(bool ok, const QString& what);
    void countingRules();

    const MatrixOptions& m_options;
    QTextStream& m_log;
    int m_failed = 0;
};

} // namespace opentop::faultmatrix
