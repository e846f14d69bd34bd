#pragma once

#include "tests/faultmatrix/FaultCounts.h"
#include "tests/faultmatrix/MatrixOptions.h"

#include <QTextStream>
#include <QVector>

namespace opentop::faultmatrix {

// --late-sweep (issue 28): the same seeds with only late replies, at each rate and each delay
// of a reply, to show that no late reply is ever taken for the answer to another request. One
// row per rate and delay: false compare rows, misreads, needless writes (all must be 0).
class LateSweep
{
public:
    LateSweep(const MatrixOptions& options, QTextStream& out);

    // Every row; false when a must-be-0 count is not 0.
    bool run();

private:
    struct Row
    {
        int baud = 0;
        int delayMs = 0;
        FaultCounts counts;
    };
    void printTable(const QVector<Row>& rows) const;

    const MatrixOptions& m_options;
    QTextStream& m_out;
};

} // namespace opentop::faultmatrix
