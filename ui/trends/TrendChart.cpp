#include "trends/TrendChart.h"

#include "bus/BusDrives.h"
#include "monitor/MonitorHub.h"
#include "monitor/TrendCsv.h"
#include "session/DeviceSession.h"
#include "trends/TrendChartView.h"
#include "trends/TrendPoints.h"
#include "trends/TrendReadout.h"

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
#include <limits>

namespace opentop {

namespace {

constexpr int kRedrawMs = 200;      // 5 Hz is smooth enough to watch and cheap
constexpr qint64 kMinSpanMs = 1000; // zooming further shows nothing useful

// One colour per drive, one dash pattern per quantity of a drive.
QPen penFor(int driveIndex, int quantityIndex)
{
    static const QColor colours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28),
                                     QColor(0x2c, 0xa0, 0x2c), QColor(0xff, 0x7f, 0x0e),
                                     QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                     QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf)};
    static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine,
                                          Qt::DashDotLine};
    QPen pen(colours[driveIndex % 8], 2);
    pen.setStyle(styles[quantityIndex % 4]);
    return pen;
}

} // namespace

TrendChart::TrendChart(MonitorHub* hub, QWidget* parent)
    : QWidget(parent)
    , m_hub(hub)
    , m_chart(new QChart)
    , m_view(new TrendChartView(m_chart, this))
    , m_readout(new QLabel(this))
    , m_timeAxis(new QDateTimeAxis(m_chart))
    , m_axes(m_chart)
{
    // Line samples in the legend: the dash pattern tells a drive's quantities apart.
    m_chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    m_timeAxis->setFormat(QStringLiteral("hh:mm:ss"));
    m_timeAxis->setTitleText(tr("Time (hh:mm:ss)"));
    m_timeAxis->setTickCount(7);
    m_chart->addAxis(m_timeAxis, Qt::AlignBottom);
    m_view->setMinimumSize(320, 220);

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
    // Identified again (another model at the number): the names must say so.
    connect(hub->drives(), &BusDrives::driveChanged, this, [this](int slave) {
        for (const Line& line : std::as_const(m_lines)) {
            if (line.source.slave == slave)
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
    const QString name = info.shortModel(); // "DBU" while the variant is unknown
    return name.isEmpty() ? tr("Drive %1").arg(slave)
                          : QStringLiteral("%1 %2").arg(slave).arg(name);
}

QString TrendChart::seriesName(const TrendSource& source) const
{
    for (const Line& line : m_lines) {
        if (line.source == source)
            return QStringLiteral("%1 %2").arg(driveTitle(drives(), source.slave), line.label);
    }
    return QString();
}

const TrendHistory::Series* TrendChart::historyOf(const TrendSource& source) const
{
    // Looked up each time: the hub drops a drive's history when the drive is removed.
    const TrendHistory* history = m_hub ? m_hub->history(source.slave) : nullptr;
    return history ? history->find(source.key) : nullptr;
}

void TrendChart::describe(Line& line) const
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

void TrendChart::setSources(const QVector<TrendSource>& sources)
{
    if (sources == this->sources())
        return;
    watch(false);
    m_lines.clear();
    for (const TrendSource& s : sources) {
        Line line;
        line.source = s;
        describe(line);
        m_lines << line;
    }
    rebuild();
    if (isVisible())
        watch(true);
    refresh();
}

QVector<TrendSource> TrendChart::sources() const
{
    QVector<TrendSource> list;
    for (const Line& line : m_lines)
        list << line.source;
    return list;
}

void TrendChart::rebuild()
{
    m_chart->removeAllSeries();
    QVector<QPair<QString, QString>> quantities;
    for (const Line& line : m_lines)
        quantities << qMakePair(line.label, line.unit);
    m_axes.setQuantities(quantities);

    // Names elided in a row under the chart could be misread: a column beside it when many.
    m_chart->legend()->setAlignment(m_lines.size() > 3 ? Qt::AlignRight : Qt::AlignBottom);
    QVector<int> slaves;
    for (Line& line : m_lines) {
        if (!slaves.contains(line.source.slave))
            slaves << line.source.slave;
        int quantity = 0;
        for (const Line& other : m_lines) {
            if (&other == &line)
                break;
            quantity += other.source.slave == line.source.slave ? 1 : 0;
        }
        line.series = new QLineSeries(m_chart);
        line.series->setName(seriesName(line.source));
        line.series->setPen(penFor(int(slaves.indexOf(line.source.slave)), quantity));
        m_chart->addSeries(line.series);
        line.series->attachAxis(m_timeAxis);
        line.series->attachAxis(m_axes.axis(m_axes.sideOf(line.unit)));
        line.drawnCount = -1;
    }
}

void TrendChart::watch(bool on)
{
    if (on == m_watching || !m_hub)
        return;
    m_watching = on;
    QSet<int> slaves;
    for (const Line& line : m_lines)
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
    m_timeAxis->setRange(QDateTime::fromMSecsSinceEpoch(m_from),
                         QDateTime::fromMSecsSinceEpoch(m_to));
    // Lines whose history had no unit yet when they were added get their axis now.
    bool changed = false;
    for (Line& line : m_lines) {
        const QString unit = line.unit;
        const QString label = line.label;
        describe(line);
        changed = changed || unit != line.unit || label != line.label;
    }
    if (changed)
        rebuild();
    // At most about two points per pixel column are worth drawing.
    const int buckets = std::max(100, int(m_chart->plotArea().width()));
    for (Line& line : m_lines)
        drawLine(line, buckets);
    m_axes.fitTitles(m_chart->plotArea().height());
    updateValueAxes();
    if (m_markers[0] || m_markers[1])
        updateReadout();
}

void TrendChart::drawLine(Line& line, int buckets)
{
    const TrendHistory::Series* s = historyOf(line.source);
    const int count = s ? int(s->points.size()) : 0;
    const qint64 last = count ? s->points.last().ms : -1;
    if (line.drawnFrom == m_from && line.drawnTo == m_to && line.drawnCount == count &&
        line.drawnLast == last)
        return;
    line.drawnFrom = m_from;
    line.drawnTo = m_to;
    line.drawnCount = count;
    line.drawnLast = last;
    line.series->replace(s ? TrendPoints::visible(*s, m_from, m_to, buckets) : QList<QPointF>());
}

void TrendChart::updateValueAxes()
{
    for (int side : {0, 1}) {
        double lo = std::numeric_limits<double>::max();
        double hi = std::numeric_limits<double>::lowest();
        for (const Line& line : m_lines) {
            if (m_axes.sideOf(line.unit) != side)
                continue;
            for (const QPointF& p : line.series->points()) {
                if (p.x() >= double(m_from) && p.x() <= double(m_to)) {
                    lo = std::min(lo, p.y());
                    hi = std::max(hi, p.y());
                }
            }
        }
        m_axes.setRange(side, lo, hi);
    }
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
    for (const Line& line : m_lines)
        rows << TrendReadout::Row{line.series ? line.series->name() : QString(), line.unit,
                                  historyOf(line.source)};
    return TrendReadout::text(rows, m_markers[0], m_markers[1]);
}

void TrendChart::updateReadout()
{
    m_readout->setText(markerText());
}

bool TrendChart::exportCsv(const QString& path, QString* error) const
{
    QVector<TrendCsv::Column> columns;
    for (const Line& line : m_lines) {
        if (const TrendHistory::Series* s = historyOf(line.source))
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
