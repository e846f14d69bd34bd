#pragma once

#include <QChartView>
#include <array>
#include <optional>

class QRubberBand;
class QDateTimeAxis;

namespace opentop {

// The chart view of a TrendChart: turns mouse gestures into time-axis requests (a click places
// a marker, a horizontal drag or the wheel zooms) and draws markers A and B as vertical lines.
// Its own rubber band, not QChartView's: that one zooms on a plain click and on a right click.
class TrendChartView : public QChartView
{
    Q_OBJECT
public:
    explicit TrendChartView(QChart* chart, QWidget* parent = nullptr);

    void setMarkers(std::optional<qint64> a, std::optional<qint64> b);
    // The time at view position `x` and back, by the chart's time axis; std::nullopt without one.
    std::optional<qint64> msAt(double x) const;
    std::optional<double> xAt(qint64 ms) const;

signals:
    void clicked(qint64 ms);
    void rangeSelected(qint64 fromMs, qint64 toMs);
    // factor < 1 zooms in around centerMs.
    void wheelZoom(qint64 centerMs, double factor);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void drawForeground(QPainter* painter, const QRectF& rect) override;

private:
    QDateTimeAxis* timeAxis() const;
    QRectF plotInView() const;

    QRubberBand* m_band;
    QPoint m_origin;
    bool m_pressed = false;
    bool m_dragging = false;
    std::array<std::optional<qint64>, 2> m_markers;
};

} // namespace opentop
