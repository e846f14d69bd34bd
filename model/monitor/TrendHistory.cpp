#include "model/monitor/TrendHistory.h"

#include "model/monitor/DeviceMonitor.h"
#include "model/profile/ParameterMeta.h"

#include <algorithm>

namespace opentop {

TrendHistory::TrendHistory(int capacity)
    : m_capacity(std::max(10, capacity))
{
}

TrendHistory::Series& TrendHistory::seriesFor(const QString& key, const QString& label,
                                              const QString& unit)
{
    for (Series& s : m_series) {
        if (s.key == key)
            return s;
    }
    m_series.append(Series{key, label, unit, {}});
    m_series.last().points.reserve(std::min(m_capacity, 1024));
    return m_series.last();
}

void TrendHistory::append(const MonitorSample& sample)
{
    const qint64 ms = sample.timestamp.toMSecsSinceEpoch();
    for (const MonitorValue& v : sample.values) {
        if (!v.meta || !v.value.valid || !v.meta->isNumeric() || !v.meta->spec.options.isEmpty())
            continue;
        // Speed registers hold the magnitude; the trend shows reverse below zero.
        const double value = sample.signedSpeed(v.meta->name).value_or(v.value.number);
        Series& s = seriesFor(v.meta->name, v.meta->label, v.meta->spec.unit);
        if (!s.points.isEmpty() && s.points.last().ms > ms)
            continue; // time never runs backwards in a chart
        s.points.append(Point{ms, value});
        // Trim in chunks so that appending stays cheap.
        if (s.points.size() > m_capacity)
            s.points.remove(0, s.points.size() - m_capacity + m_capacity / 10);
    }
}

void TrendHistory::clear()
{
    m_series.clear();
}

void TrendHistory::setCapacity(int capacity)
{
    m_capacity = std::max(10, capacity);
    for (Series& s : m_series) {
        if (s.points.size() > m_capacity) {
            s.points.remove(0, s.points.size() - m_capacity);
            s.points.squeeze();
        }
    }
}

qint64 TrendHistory::pointCount() const
{
    qint64 n = 0;
    for (const Series& s : m_series)
        n += s.points.size();
    return n;
}

const TrendHistory::Series* TrendHistory::find(const QString& key) const
{
    for (const Series& s : m_series) {
        if (s.key == key)
            return &s;
    }
    return nullptr;
}

int TrendHistory::lowerBound(const Series& series, qint64 ms)
{
    const auto it = std::lower_bound(series.points.cbegin(), series.points.cend(), ms,
                                     [](const Point& p, qint64 t) { return p.ms < t; });
    return int(it - series.points.cbegin());
}

bool TrendHistory::valueAt(const Series& series, qint64 ms, double* value)
{
    const auto it = std::upper_bound(series.points.cbegin(), series.points.cend(), ms,
                                     [](qint64 t, const Point& p) { return t < p.ms; });
    if (it == series.points.cbegin())
        return false;
    *value = std::prev(it)->value;
    return true;
}

} // namespace opentop
