#include "ui/trends/TrendLines.h"

#include "model/bus/BusDrives.h"
#include "model/session/DeviceSession.h"
#include "model/session/Freshness.h"
#include "ui/trends/TrendAxes.h"
#include "ui/trends/TrendPoints.h"

#include <QChart>
#include <QDateTimeAxis>
#include <QLegend>
#include <QLineSeries>
#include <QValueAxis>
#include <limits>

namespace opentop {

namespace {

// One colour per line, so that a drive's current speed, target and load differ at a glance;
// the dash pattern tells the drives apart as well.
QPen penFor(int lineIndex, int driveIndex)
{
    static const QColor colours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28),
                                     QColor(0x2c, 0xa0, 0x2c), QColor(0xff, 0x7f, 0x0e),
                                     QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                     QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf)};
    static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine,
                                          Qt::DashDotLine};
    QPen pen(colours[lineIndex % 8], 2);
    pen.setStyle(styles[driveIndex % 4]);
    return pen;
}

} // namespace

TrendLines::TrendLines(MonitorHub* hub, QChart* chart, QDateTimeAxis* timeAxis, TrendAxes* axes)
    : m_hub(hub)
    , m_chart(chart)
    , m_timeAxis(timeAxis)
    , m_axes(axes)
{
}

void TrendLines::setSources(const QVector<TrendSource>& sources)
{
    m_lines.clear();
    for (const TrendSource& s : sources) {
        Line line;
        line.source = s;
        describe(line);
        m_lines << line;
    }
}

QVector<TrendSource> TrendLines::sources() const
{
    QVector<TrendSource> list;
    for (const Line& line : m_lines)
        list << line.source;
    return list;
}

const TrendHistory::Series* TrendLines::historyOf(const TrendSource& source) const
{
    const TrendHistory* history = m_hub ? m_hub->history(source.slave) : nullptr;
    return history ? history->find(source.key) : nullptr;
}

void TrendLines::describe(Line& line) const
{
    if (const TrendHistory::Series* s = historyOf(line.source)) {
        line.label = s->label;
        line.unit = s->unit;
        return;
    }
    // Before the first sample: what the profile says.
    const DeviceSession* session = m_hub ? m_hub->drives()->session(line.source.slave) : nullptr;
    const ParameterMeta* meta = session ? session->profile().parameter(line.source.key) : nullptr;
    line.label = meta ? meta->label : line.source.key;
    line.unit = meta ? meta->spec.unit : QString();
}

bool TrendLines::describeAgain()
{
    bool changed = false;
    for (Line& line : m_lines) {
        const QString unit = line.unit;
        const QString label = line.label;
        describe(line);
        changed = changed || unit != line.unit || label != line.label;
    }
    return changed;
}

void TrendLines::rebuild(const NameOf& nameOf)
{
    m_chart->removeAllSeries();
    QVector<QPair<QString, QString>> quantities;
    for (const Line& line : m_lines)
        quantities << qMakePair(line.label, line.unit);
    m_axes->setQuantities(quantities);

    // Names elided in a row under the chart could be misread: a column beside it when many.
    m_chart->legend()->setAlignment(m_lines.size() > 3 ? Qt::AlignRight : Qt::AlignBottom);
    QVector<int> slaves;
    int index = 0;
    for (Line& line : m_lines) {
        if (!slaves.contains(line.source.slave))
            slaves << line.source.slave;
        line.drawn.clear();
        line.series = new QLineSeries(m_chart);
        line.series->setName(nameOf(line.source));
        line.series->setPen(penFor(index++, int(slaves.indexOf(line.source.slave))));
        m_chart->addSeries(line.series);
        line.series->attachAxis(m_timeAxis);
        line.series->attachAxis(m_axes->axis(m_axes->sideOf(line.unit)));
        line.drawnCount = -1;
    }
}

void TrendLines::draw(qint64 fromMs, qint64 toMs, int buckets)
{
    // The visible points of the lines whose history or window changed since they were drawn.
    QVector<std::optional<Segments>> next(m_lines.size());
    for (int i = 0; i < m_lines.size(); ++i)
        next[i] = pointsToDraw(m_lines[i], fromMs, toMs, buckets);
    m_timeAxis->setRange(QDateTime::fromMSecsSinceEpoch(fromMs),
                         QDateTime::fromMSecsSinceEpoch(toMs));
    fitValueAxes(next, fromMs, toMs);
    for (int i = 0; i < m_lines.size(); ++i) {
        if (next[i])
            m_lines[i].drawn = std::move(*next[i]);
    }
}

std::optional<TrendLines::Segments> TrendLines::pointsToDraw(Line& line, qint64 fromMs, qint64 toMs,
                                                             int buckets) const
{
    const TrendHistory::Series* s = historyOf(line.source);
    const int count = s ? int(s->points.size()) : 0;
    const qint64 last = count ? s->points.last().ms : -1;
    if (line.drawnFrom == fromMs && line.drawnTo == toMs && line.drawnCount == count &&
        line.drawnLast == last)
        return std::nullopt;
    line.drawnFrom = fromMs;
    line.drawnTo = toMs;
    line.drawnCount = count;
    line.drawnLast = last;
    // A gap in the history (polling stopped, no answer) is longer than a value stays live.
    const qint64 gapMs = Freshness::staleAfterMs(m_hub ? m_hub->interval() : 200);
    Segments parts = s ? TrendPoints::segments(*s, fromMs, toMs, buckets, gapMs) : Segments();
    for (QList<QPointF>& part : parts)
        TrendPoints::dropRepeats(&part, fromMs, toMs, gapMs);
    return parts;
}

void TrendLines::fitValueAxes(const QVector<std::optional<Segments>>& next, qint64 fromMs,
                              qint64 toMs)
{
    for (int side : {0, 1}) {
        double lo = std::numeric_limits<double>::max();
        double hi = std::numeric_limits<double>::lowest();
        const auto include = [&](const QList<QPointF>& points) {
            for (const QPointF& p : points) {
                if (p.x() >= double(fromMs) && p.x() <= double(toMs)) {
                    lo = std::min(lo, p.y());
                    hi = std::max(hi, p.y());
                }
            }
        };
        for (int i = 0; i < m_lines.size(); ++i) {
            const Line& line = m_lines[i];
            if (m_axes->sideOf(line.unit) != side)
                continue;
            if (next[i]) {
                for (const QList<QPointF>& part : *next[i])
                    include(part);
            } else {
                for (const QList<QPointF>& part : line.drawn)
                    include(part);
            }
        }
        m_axes->setRange(side, lo, hi);
    }
}

} // namespace opentop
