#pragma once

#include "model/monitor/MonitorHub.h"
#include "model/monitor/TrendHistory.h"

#include <QList>
#include <QPointF>
#include <QPointer>
#include <QString>
#include <QVector>
#include <functional>
#include <optional>

class QChart;
class QDateTimeAxis;
class QLineSeries;

namespace opentop {

class TrendAxes;

// One series of a trend chart: a numeric monitor quantity of one drive.
struct TrendSource
{
    int slave = 0;
    QString key; // TrendHistory series key: "status.current_speed"
};

inline bool operator==(const TrendSource& a, const TrendSource& b)
{
    return a.slave == b.slave && a.key == b.key;
}

// The lines of a trend chart: each source's label and unit (from the hub's history, or from
// the profile before the first sample), its series on the chart with a pen per drive and
// quantity and the value axis of its unit, and the visible points it shows, split into
// segments where the history has a gap (a gap is never drawn as a line). TrendCanvas draws
// the points; the series holds none, as QtCharts lays out and strokes every point of a series
// again on each change (at 64 drives that was most of the program's time). Remembers what
// each line drew last, so that an unchanged frozen view is not drawn again.
class TrendLines
{
public:
    struct Line
    {
        TrendSource source;
        QString label;
        QString unit;
        QLineSeries* series = nullptr; // in the legend, with the pen and the axes; no points
        QVector<QList<QPointF>> drawn; // the segments shown, split where the history has a gap
        qint64 drawnFrom = -1;
        qint64 drawnTo = -1;
        qint64 drawnLast = -1;
        int drawnCount = -1;
    };
    using NameOf = std::function<QString(const TrendSource&)>;

    TrendLines(MonitorHub* hub, QChart* chart, QDateTimeAxis* timeAxis, TrendAxes* axes);

    // New sources, described; rebuild() puts them on the chart.
    void setSources(const QVector<TrendSource>& sources);
    QVector<TrendSource> sources() const;
    const QVector<Line>& lines() const { return m_lines; }
    // Looked up each time: the hub drops a drive's history when the drive is removed.
    const TrendHistory::Series* historyOf(const TrendSource& source) const;

    // The chart's series, pens and axes for the current lines, each named by `nameOf`.
    void rebuild(const NameOf& nameOf);
    // Describes every line again; true when a label or unit changed (rebuild() then).
    bool describeAgain();
    // The points of [fromMs, toMs], thinned to `buckets`, on the time axis set to that range
    // and the value axes fitted to the points in it.
    void draw(qint64 fromMs, qint64 toMs, int buckets);

private:
    using Segments = QVector<QList<QPointF>>;

    void describe(Line& line) const;
    // The points `line` is to show; none when it shows them already.
    std::optional<Segments> pointsToDraw(Line& line, qint64 fromMs, qint64 toMs, int buckets) const;
    // Each value axis fitted to the points in [fromMs, toMs] its lines are to show (`next`)
    // or show.
    void fitValueAxes(const QVector<std::optional<Segments>>& next, qint64 fromMs, qint64 toMs);

    QPointer<MonitorHub> m_hub; // the chart may outlive it while a window closes
    QChart* m_chart;
    QDateTimeAxis* m_timeAxis;
    TrendAxes* m_axes;
    QVector<Line> m_lines;
};

} // namespace opentop
