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

// Draws the lines of a trend chart over its plot area, from the points TrendLines keeps. The
// series stay on the chart for the legend and the axes, without points: QtCharts lays out
// and strokes every point of a series again on each change (a dashed line as one path, about
// six times the cost of the straight pieces this item draws), and at 48 to 192 lines five
// times a second that was most of the program's time.
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
