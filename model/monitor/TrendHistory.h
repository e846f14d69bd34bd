#pragma once

#include <QString>
#include <QVector>

namespace opentop {

struct MonitorSample;

// The recent values of one drive for trend charts: one bounded time series per numeric
// quantity of its monitor samples (speeds signed by the direction, load, PWM, current...).
// Enumerations and bit sets are states, not trends, and are left out.
class TrendHistory
{
public:
    struct Point
    {
        qint64 ms = 0; // milliseconds since the epoch
        double value = 0;
    };

    struct Series
    {
        QString key;   // the parameter name: "status.current_speed"
        QString label; // "Current speed"
        QString unit;  // "r/min"
        QVector<Point> points;
    };

    // `capacity`: points kept per series; the oldest go first. 36000 = one hour at 10 Hz.
    explicit TrendHistory(int capacity = 36000);

    void append(const MonitorSample& sample);
    void clear();

    const QVector<Series>& series() const { return m_series; }
    const Series* find(const QString& key) const;
    int capacity() const { return m_capacity; }
    // A new capacity; series longer than it lose their oldest points now.
    void setCapacity(int capacity);
    // Points held in all series (what the history costs: sizeof(Point) each).
    qint64 pointCount() const;
    // The index of the first point at or after `ms` (points.size() when there is none).
    static int lowerBound(const Series& series, qint64 ms);
    // The value at `ms`: the newest point at or before it; false when there is none.
    static bool valueAt(const Series& series, qint64 ms, double* value);

private:
    Series& seriesFor(const QString& key, const QString& label, const QString& unit);

    int m_capacity;
    QVector<Series> m_series;
};

} // namespace opentop
