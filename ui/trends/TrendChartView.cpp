#include "ui/trends/TrendChartView.h"

#include <QDateTime>
#include <QDateTimeAxis>
#include <QMouseEvent>
#include <QRubberBand>
#include <QWheelEvent>
#include <algorithm>
#include <cstdlib>

namespace opentop {

namespace {

// Moves shorter than this are clicks, not drags.
constexpr int kDragPixels = 5;

} // namespace

TrendChartView::TrendChartView(QChart* chart, QWidget* parent)
    : QChartView(chart, parent)
    , m_band(new QRubberBand(QRubberBand::Rectangle, viewport()))
{
    setRubberBand(QChartView::NoRubberBand);
    setRenderHint(QPainter::Antialiasing);
    setMouseTracking(false);
    // The markers are painted over the scene: a partial update after the time axis scrolled
    // would leave their old labels behind.
    setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
}

void TrendChartView::setMarkers(std::optional<qint64> a, std::optional<qint64> b)
{
    m_markers = {a, b};
    // The foreground is not part of the scene: repaint it ourselves.
    scene()->update();
    viewport()->update();
}

QDateTimeAxis* TrendChartView::timeAxis() const
{
    const auto axes = chart()->axes(Qt::Horizontal);
    return axes.isEmpty() ? nullptr : qobject_cast<QDateTimeAxis*>(axes.first());
}

QRectF TrendChartView::plotInView() const
{
    const QRectF plot = chart()->plotArea();
    return QRectF(mapFromScene(chart()->mapToScene(plot.topLeft())),
                  mapFromScene(chart()->mapToScene(plot.bottomRight())));
}

std::optional<qint64> TrendChartView::msAt(double x) const
{
    const QDateTimeAxis* axis = timeAxis();
    const QRectF plot = plotInView();
    if (!axis || plot.width() <= 0)
        return std::nullopt;
    const qint64 min = axis->min().toMSecsSinceEpoch();
    const qint64 max = axis->max().toMSecsSinceEpoch();
    const double f = std::clamp((x - plot.left()) / plot.width(), 0.0, 1.0);
    return min + qint64(f * double(max - min) + 0.5);
}

std::optional<double> TrendChartView::xAt(qint64 ms) const
{
    const QDateTimeAxis* axis = timeAxis();
    const QRectF plot = plotInView();
    if (!axis)
        return std::nullopt;
    const qint64 min = axis->min().toMSecsSinceEpoch();
    const qint64 max = axis->max().toMSecsSinceEpoch();
    if (max <= min || ms < min || ms > max)
        return std::nullopt;
    return plot.left() + plot.width() * double(ms - min) / double(max - min);
}

void TrendChartView::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || !plotInView().contains(event->position())) {
        QChartView::mousePressEvent(event);
        return;
    }
    m_pressed = true;
    m_dragging = false;
    m_origin = event->position().toPoint();
    event->accept();
}

void TrendChartView::mouseMoveEvent(QMouseEvent* event)
{
    if (!m_pressed) {
        QChartView::mouseMoveEvent(event);
        return;
    }
    const QPoint pos = event->position().toPoint();
    if (!m_dragging && std::abs(pos.x() - m_origin.x()) < kDragPixels)
        return;
    m_dragging = true;
    // Horizontal band over the whole plot height: only time is zoomed.
    const QRectF plot = plotInView();
    const int left = std::max(int(plot.left()), std::min(m_origin.x(), pos.x()));
    const int right = std::min(int(plot.right()), std::max(m_origin.x(), pos.x()));
    m_band->setGeometry(
        QRect(left, int(plot.top()), std::max(1, right - left), int(plot.height())));
    m_band->show();
    event->accept();
}

void TrendChartView::mouseReleaseEvent(QMouseEvent* event)
{
    if (!m_pressed || event->button() != Qt::LeftButton) {
        QChartView::mouseReleaseEvent(event);
        return;
    }
    m_pressed = false;
    m_band->hide();
    const double x = event->position().x();
    if (m_dragging) {
        const auto a = msAt(std::min<double>(m_origin.x(), x));
        const auto b = msAt(std::max<double>(m_origin.x(), x));
        if (a && b && *b > *a)
            emit rangeSelected(*a, *b);
    } else if (const auto ms = msAt(x)) {
        emit clicked(*ms);
    }
    m_dragging = false;
    event->accept();
}

void TrendChartView::wheelEvent(QWheelEvent* event)
{
    const auto center = msAt(event->position().x());
    const int delta = event->angleDelta().y();
    if (!center || delta == 0) {
        event->ignore();
        return;
    }
    emit wheelZoom(*center, delta > 0 ? 0.8 : 1.25);
    event->accept();
}

void TrendChartView::drawForeground(QPainter* painter, const QRectF& rect)
{
    QChartView::drawForeground(painter, rect);
    const QRectF plot = chart()->plotArea();
    static const char* const names[] = {"A", "B"};
    static const QColor colours[] = {QColor(0xC0, 0x00, 0x00), QColor(0x00, 0x40, 0xC0)};
    for (int i = 0; i < 2; ++i) {
        if (!m_markers[i])
            continue;
        const auto x = xAt(*m_markers[i]);
        if (!x)
            continue;
        // Painting happens in scene coordinates.
        const double sx = mapToScene(QPoint(int(*x), 0)).x();
        const double top = chart()->mapToScene(plot.topLeft()).y();
        const double bottom = chart()->mapToScene(plot.bottomLeft()).y();
        painter->save();
        painter->setPen(QPen(colours[i], 1.5, Qt::DashLine));
        painter->drawLine(QPointF(sx, top), QPointF(sx, bottom));
        QFont font = painter->font();
        font.setBold(true);
        painter->setFont(font);
        const QString name = QLatin1String(names[i]);
        const QRectF box(sx + 2, top + 2, painter->fontMetrics().horizontalAdvance(name) + 6,
                         painter->fontMetrics().height() + 2);
        painter->fillRect(box, Qt::white);
        painter->setPen(colours[i]);
        painter->drawText(box, Qt::AlignCenter, name);
        painter->restore();
    }
}

} // namespace opentop
