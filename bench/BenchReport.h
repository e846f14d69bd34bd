#pragma once

#include "bench/BenchFigure.h"

#include <QStringList>
#include <QTextStream>
#include <QVector>

namespace opentop {

// Prints figures as they are measured, one per line, each goal with "met" or "MISSED", and
// keeps them for the summary and the exit status.
class BenchReport
{
public:
    explicit BenchReport(QTextStream& out);

    void add(const BenchFigure& figure);
    void note(const QString& text); // a line of context (what ran, against what)
    void failed(const QString& benchmark, const QString& error);

    const QVector<BenchFigure>& figures() const { return m_figures; }
    QStringList missedGoals() const;
    QStringList failures() const { return m_failures; }
    void printSummary();

private:
    QTextStream& m_out;
    QVector<BenchFigure> m_figures;
    QStringList m_failures;
};

} // namespace opentop
