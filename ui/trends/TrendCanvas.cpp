#include "ui/trends/TrendCanvas.h"

#include "ui/trends/TrendLines.h"

#include <QChart>
#include <QDateTimeAxis>
#include <QLineSeries>
#include <QPainter>
#include <QValueAxis>

namespace opentop {

namespace {

// Where the chart puts a value: linear in both axes, as QtCharts maps them.
struct Mapping
{
    double x0 = 0;
    double xScale = 0;
    double y0 = 0;
    double yScale = 0;
    QPointF operator()(const QPointF& p) const
    {
        return QPointF(x0 + p.x() * xScale, y0 - p.y() * yScale);
    }
};

bool mappingFor(QLineSeries* series, const QRectF& plot, Mapping* m)
{
    double minX = 0;
    double maxX = 0;
    double minY = 0;
    double maxY = 0;
    bool x = false;
    bool y = false;
    for (const QAbstractAxis* axis : series->attachedAxes()) {
        if (const auto* time = qobject_cast<const QDateTimeAxis*>(axis)) {
            minX = double(time->min().toMSecsSinceEpoch());
            maxX = double(time->max().toMSecsSinceEpoch());
            x = true;
        } else if (const auto* value = qobject_cast<const QValueAxis*>(axis)) {
            minY = value->min();
            maxY = value->max();
            y = true;
        }
    }
    if (!x || !y || maxX <= minX || maxY <= minY)
        return false;
    m->xScale = plot.width() / (maxX - minX);
    m->x0 = plot.left() - minX * m->xScale;
    m->yScale = plot.height() / (maxY - minY);
    m->y0 = plot.bottom() + minY * m->yScale;
    return true;
}

} // namespace

TrendCanvas::TrendCanvas(const TrendLines* lines, QChart* chart)
    : QGraphicsItem(chart)
    , m_lines(lines)
    , m_chart(chart)
    , m_plot(chart->plotArea())
{
    // Over the grid and the series, under nothing else: the plot area holds only those.
    setZValue(1000);
}

QRectF TrendCanvas::boundingRect() const
{
    return m_plot;
}

void TrendCanvas::plotAreaChanged()
{
    prepareGeometryChange();
    m_plot = m_chart->plotArea();
    update();
}

QVector<QLineF> TrendCanvas::pieces(const QList<QPointF>& points, const QPen& pen)
{
    QVector<QLineF> out;
    if (points.size() < 2)
        return out;
    if (pen.style() == Qt::SolidLine) {
        out.reserve(points.size() - 1);
        for (int i = 1; i < points.size(); ++i)
            out << QLineF(points[i - 1], points[i]);
        return out;
    }
    // The pattern is in pen widths, dashes and gaps taking turns, as QPen has it.
    const QList<qreal> pattern = pen.dashPattern();
    const qreal width = std::max<qreal>(1, pen.widthF());
    if (pattern.isEmpty())
        return out;
    int index = 0;
    qreal left = pattern[0] * width;
    bool on = true;
    for (int i = 1; i < points.size(); ++i) {
        QPointF a = points[i - 1];
        const QPointF b = points[i];
        qreal length = QLineF(a, b).length();
        while (length > 0) {
            const qreal step = std::min(length, left);
            const QPointF c = a + (b - a) * (step / length);
            if (on && step > 0)
                out << QLineF(a, c);
            a = c;
            length -= step;
            left -= step;
            if (left <= 1e-9) {
                index = (index + 1) % int(pattern.size());
                left = pattern[index] * width;
                on = !on;
            }
        }
    }
    return out;
}

void TrendCanvas::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    painter->save();
    painter->setClipRect(m_plot);
    for (const TrendLines::Line& line : m_lines->lines()) {
        if (!line.series)
            continue;
        Mapping map;
        if (!mappingFor(line.series, m_plot, &map))
            continue;
        const QPen pen = line.series->pen();
        // Each piece is a straight line the raster engine draws fast; a dash's pieces meet
        // under their square caps as a stroked path's would.
        QPen solid = pen;
        solid.setStyle(Qt::SolidLine);
        painter->setPen(solid);
        for (QList<QPointF> points : line.drawn) {
            for (QPointF& p : points)
                p = map(p);
            painter->drawLines(pieces(points, pen));
        }
    }
    painter->restore();
}

} // namespace opentop
