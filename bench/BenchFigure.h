#pragma once

#include <QString>

namespace opentop {

// One measured number, e.g. "scan.19200.t2.time 4.52 s", with the goal it is judged by.
struct BenchFigure
{
    enum class Goal
    {
        None,
        AtMost,
        AtLeast
    };

    QString name;
    double value = 0;
    QString unit; // empty for counts; "x" for ratios
    int decimals = 1;
    Goal goal = Goal::None;
    double limit = 0;
    QString note; // what the figure is measured against, in a few words

    static BenchFigure plain(const QString& name, double value, const QString& unit,
                             int decimals = 1, const QString& note = QString())
    {
        return {name, value, unit, decimals, Goal::None, 0, note};
    }
    static BenchFigure atMost(const QString& name, double value, const QString& unit, double limit,
                              int decimals = 2, const QString& note = QString())
    {
        return {name, value, unit, decimals, Goal::AtMost, limit, note};
    }
    static BenchFigure atLeast(const QString& name, double value, const QString& unit, double limit,
                               int decimals = 2, const QString& note = QString())
    {
        return {name, value, unit, decimals, Goal::AtLeast, limit, note};
    }

    bool met() const
    {
        return goal == Goal::None || (goal == Goal::AtMost ? value <= limit : value >= limit);
    }
};

} // namespace opentop
