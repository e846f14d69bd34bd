#include "ui/trends/TrendChart.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveName.h"
#include "model/monitor/MonitorHub.h"
#include "model/monitor/TrendCsv.h"
#include "ui/trends/TrendCanvas.h"
#include "ui/trends/TrendChartView.h"
#include "ui/trends/TrendReadout.h"

#include <QChart>
#include <QDateTime>
#include <QDateTimeAxis>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPixmap>
#include <QSet>
#include <QVBoxLayout>
#include <QValueAxis>

namespace opentop {

namespace {

// A short plot (a laptop's window with docks open) gives the time axis' title to the plot: the
// times under it say what it is. Shown again with room to spare, so that it does not flicker.
// The value axes keep their unit at least (TrendAxes::fitTitles).
void fitTitles(const QChart* chart, QDateTimeAxis* timeAxis, TrendAxes& axes)
{
    const double plot = chart->plotArea().height();
    const bool timeTitle = timeAxis->titleText().isEmpty() ? plot > 90 : plot >= 50;
    const QString time = timeTitle ? TrendChart::tr("Time (hh:mm:ss)") : QString();
    if (timeAxis->titleText() != time)
        timeAxis->setTitleText(time);
    axes.fitTitles(chart->plotArea().height());
}

constexpr int kRedrawMs = 200;      // 5 Hz is smooth enough to watch and cheap
constexpr qint64 kMinSpanMs = 1000; // zooming further shows nothing useful

} // namespace

TrendChart::TrendChart(MonitorHub* hub, QWidget* parent)
    : QWidget(parent)
    , m_hub(hub)
    , m_chart(new QChart)
    , m_view(new TrendChartView(m_chart, this))
    , m_readout(new QLabel(this))
    , m_timeAxis(new QDateTimeAxis(m_chart))
    , m_axes(m_chart)
    , m_lines(hub, m_chart, m_timeAxis, &m_axes)
    , m_canvas(new TrendCanvas(&m_lines, m_chart))
{
    // Line samples in the legend: colour and dash pattern as drawn.
    m_chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    m_timeAxis->setFormat(QStringLiteral("hh:mm:ss"));
    m_timeAxis->setTitleText(tr("Time (hh:mm:ss)"));
    m_timeAxis->setTickCount(7);
    m_chart->addAxis(m_timeAxis, Qt::AlignBottom);
    // A chart still, in a dock on a laptop, also where CJK text makes every row taller: its
    // plot tall enough for the unit on its axes (TrendAxes::fitTitles).
    m_view->setMinimumSize(320, 140);

    m_readout->setTextFormat(Qt::PlainText);
    m_readout->setWordWrap(true);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_readout->setObjectName(QStringLiteral("markerReadout"));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_readout);

    connect(m_view, &TrendChartView::clicked, this, &TrendChart::placeMarker);
    connect(m_view, &TrendChartView::rangeSelected, this, &TrendChart::zoomTo);
    connect(m_view, &TrendChartView::wheelZoom, this, &TrendChart::zoomAround);
    connect(&m_timer, &QTimer::timeout, this, &TrendChart::refresh);
    connect(m_chart, &QChart::plotAreaChanged, this, [this] {
        m_canvas->plotAreaChanged();
        fitTitles(m_chart, m_timeAxis, m_axes);
    });
    // Identified again (another model at the number): the names must say so.
    connect(hub->drives(), &BusDrives::driveChanged, this, [this](int slave) {
        for (const TrendLines::Line& line : m_lines.lines()) {
            if (line.source.slave == slave && line.series)
                line.series->setName(seriesName(line.source));
        }
    });
    m_timer.setInterval(kRedrawMs);
    m_to = QDateTime::currentMSecsSinceEpoch();
    m_from = m_to - m_windowMs;
    updateReadout();
}

TrendChart::~TrendChart()
{
    watch(false);
}

QString TrendChart::driveTitle(const BusDrives* drives, int slave)
{
    const DeviceInfo info = drives ? drives->info(slave) : DeviceInfo();
    // The machine's name where it has one: "1 (Infeed conveyor 3)", in the legend and the CSV.
    if (!info.machineName.isEmpty())
        return DriveName::listed(slave, info.machineName);
    const QString name = info.shortModel(); // "DBU" while the variant is unknown
    return name.isEmpty() ? tr("Drive %1").arg(slave)
                          : QStringLiteral("%1 %2").arg(slave).arg(name);
}

QString TrendChart::seriesName(const TrendSource& source) const
{
    for (const TrendLines::Line& line : m_lines.lines()) {
        if (line.source == source)
            return QStringLiteral("%1 %2").arg(driveTitle(drives(), source.slave), line.label);
    }
    return QString();
}

void TrendChart::setSources(const QVector<TrendSource>& sources)
{
    if (sources == this->sources())
        return;
    watch(false);
    m_lines.setSources(sources);
    rebuild();
    if (isVisible())
        watch(true);
    refresh();
}

QVector<TrendSource> TrendChart::sources() const
{
    return m_lines.sources();
}

void TrendChart::rebuild()
{
    m_lines.rebuild([this](const TrendSource& source) { return seriesName(source); });
    m_canvas->update();
}

void TrendChart::watch(bool on)
{
    if (on == m_watching || !m_hub)
        return;
    m_watching = on;
    QSet<int> slaves;
    for (const TrendLines::Line& line : m_lines.lines())
        slaves.insert(line.source.slave);
    for (int slave : slaves) {
        if (on)
            m_hub->watch(slave, this);
        else
            m_hub->unwatch(slave, this);
    }
}

void TrendChart::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    watch(true);
    m_timer.start();
    refresh();
}

void TrendChart::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    watch(false);
    m_timer.stop();
}

void TrendChart::setWindowSeconds(int seconds)
{
    m_windowMs = std::max(1, seconds) * 1000;
    refresh();
}

void TrendChart::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    if (paused)
        refresh(); // freeze what has arrived up to now, not the last redraw
    m_paused = paused;
    emit pausedChanged(paused);
    emit followingChanged(isFollowing());
    refresh();
}

void TrendChart::setFollowing(bool following)
{
    if (following == m_following)
        return;
    m_following = following;
    emit followingChanged(isFollowing());
}

void TrendChart::resetZoom()
{
    setFollowing(true);
    setPaused(false);
    refresh();
}

void TrendChart::zoomTo(qint64 fromMs, qint64 toMs)
{
    if (toMs - fromMs < kMinSpanMs) {
        const qint64 middle = (fromMs + toMs) / 2;
        fromMs = middle - kMinSpanMs / 2;
        toMs = fromMs + kMinSpanMs;
    }
    m_from = fromMs;
    m_to = toMs;
    setFollowing(false);
    refresh();
}

void TrendChart::zoomAround(qint64 centerMs, double factor)
{
    const double from = double(centerMs) - double(centerMs - m_from) * factor;
    const double to = double(centerMs) + double(m_to - centerMs) * factor;
    zoomTo(qint64(from), qint64(to));
}

void TrendChart::refresh()
{
    if (isFollowing()) {
        m_to = QDateTime::currentMSecsSinceEpoch();
        m_from = m_to - m_windowMs;
    }
    // Lines whose history had no unit yet when they were added get their axis now.
    if (m_lines.describeAgain())
        rebuild();
    // At most about two points per pixel column are worth drawing.
    const int buckets = std::max(100, int(m_chart->plotArea().width()));
    fitTitles(m_chart, m_timeAxis, m_axes);
    m_lines.draw(m_from, m_to, buckets);
    m_canvas->update();
    if (m_markers[0] || m_markers[1])
        updateReadout();
}

void TrendChart::placeMarker(qint64 ms)
{
    setMarker(m_nextMarker, ms);
}

void TrendChart::setMarker(int index, qint64 ms)
{
    if (index < 0 || index > 1)
        return;
    m_markers[index] = ms;
    m_nextMarker = 1 - index;
    m_view->setMarkers(m_markers[0], m_markers[1]);
    updateReadout();
    emit markersChanged();
}

void TrendChart::clearMarkers()
{
    m_markers = {};
    m_nextMarker = 0;
    m_view->setMarkers(std::nullopt, std::nullopt);
    updateReadout();
    emit markersChanged();
}

std::optional<qint64> TrendChart::marker(int index) const
{
    return index == 0 || index == 1 ? m_markers[index] : std::nullopt;
}

QString TrendChart::markerText() const
{
    QVector<TrendReadout::Row> rows;
    for (const TrendLines::Line& line : m_lines.lines())
        rows << TrendReadout::Row{line.series ? line.series->name() : QString(), line.unit,
                                  m_lines.historyOf(line.source)};
    return TrendReadout::text(rows, m_markers[0], m_markers[1]);
}

void TrendChart::updateReadout()
{
    m_readout->setText(markerText());
}

bool TrendChart::exportCsv(const QString& path, QString* error) const
{
    QVector<TrendCsv::Column> columns;
    for (const TrendLines::Line& line : m_lines.lines()) {
        if (const TrendHistory::Series* s = m_lines.historyOf(line.source))
            columns << TrendCsv::Column{driveTitle(drives(), line.source.slave), s};
    }
    if (columns.isEmpty()) {
        if (error)
            *error = tr("There is no trend data to export yet.");
        return false;
    }
    return TrendCsv::write(path, columns, m_from, m_to, error);
}

bool TrendChart::exportPng(const QString& path, QString* error)
{
    refresh();
    // The whole widget: the read-out under the chart belongs to the picture.
    const QPixmap picture = grab();
    if (picture.isNull() || !picture.save(path, "PNG")) {
        if (error)
            *error = tr("Cannot write the picture %1.").arg(path);
        return false;
    }
    return true;
}

} // namespace opentop
