#pragma once

#include <QCoreApplication>
#include <QPair>
#include <QStringList>
#include <QVector>
#include <array>

class QChart;
class QValueAxis;

namespace opentop {

// The value axes of a trend chart: the first unit on the left, the others on the right (sharing
// it, with a combined title), each titled with its quantities and unit, ranges in round steps.
class TrendAxes
{
    Q_DECLARE_TR_FUNCTIONS(opentop::TrendAxes)
public:
    explicit TrendAxes(QChart* chart);

    // The quantities shown, as (label, unit), in series order.
    void setQuantities(const QVector<QPair<QString, QString>>& quantities);
    // 0 = left, 1 = right.
    int sideOf(const QString& unit) const { return m_units.indexOf(unit) == 0 ? 0 : 1; }
    QValueAxis* axis(int side) const { return m_axes[side == 0 ? 0 : 1]; }
    // Covers [lo, hi] (lo > hi: no values) with some air and round ticks.
    void setRange(int side, double lo, double hi);
    // Titles that do not fit the plot height show the shared word and the unit ("Speed
    // [r/min]") or the unit alone; Qt would cut the unit off.
    void fitTitles(double plotHeight);
    // The last word every label ends with, capitalised; empty when they differ or there is one.
    static QString sharedWord(const QStringList& labels);

private:
    std::array<QValueAxis*, 2> m_axes;
    QStringList m_units;
    // Each side's titles from the longest to the shortest: the quantities and unit, the word
    // they share and the unit, the unit in brackets, the unit alone; the longest that fits
    // the plot is shown.
    std::array<QStringList, 2> m_titles;
};

} // namespace opentop
