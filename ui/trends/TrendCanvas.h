#pragma once

#include <QGraphicsItem>
#include <QLineF>
#include <QList>
#include <QPointF>
#include <QVector>

class QChart;
class QPen;

namespace opentop {

class TrendLines;

// Draws the lines of a trend chart over its plot area, from the points its series hold. The
// series themselves stay on the chart for the legend and the axes but are not drawn by it:
// QtCharts strokes a dashed line as one path, which costs about six times as much as the
// straight pieces this item draws (48 lines of 16 drives, five times a second, were most of
// the GUI's time).
class TrendCanvas : public QGraphicsItem
{
public:
    TrendCanvas(const TrendLines* lines, QChart* chart);

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

    // The chart's plot area moved or changed its size.
    void plotAreaChanged();
    // The pieces of `points` a pen of `style` and `width` draws: every piece of a dash (the
    // pattern continuing across the points, as a stroked path has it), or every segment of a
    // solid line.
    static QVector<QLineF> pieces(const QList<QPointF>& points, const QPen& pen);

private:
    const TrendLines* m_lines;
    QChart* m_chart;
    QRectF m_plot;
};

} // namespace opentop
