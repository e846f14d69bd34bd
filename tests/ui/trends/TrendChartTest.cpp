#include "ui/trends/TrendChart.h"
#include "tests/ui/trends/TrendFixture.h"
#include "ui/trends/TrendChartView.h"
#include "ui/trends/TrendReadout.h"

#include <QChart>
#include <QDateTimeAxis>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLineSeries>
#include <QMouseEvent>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>
#include <QWheelEvent>

using namespace opentop;

namespace {

const QString kSpeed = QStringLiteral("status.current_speed");
const QString kLoad = QStringLiteral("status.load");

class TrendChartTest : public test::TrendFixture
{
protected:
    std::unique_ptr<TrendChart> makeChart(const QVector<TrendSource>& sources)
    {
        auto chart = std::make_unique<TrendChart>(hub.get());
        chart->resize(900, 600);
        chart->setSources(sources);
        chart->show();
        return chart;
    }

    static QLineSeries* line(TrendChart& chart, int index)
    {
        return qobject_cast<QLineSeries*>(chart.chart()->series().value(index));
    }

    // The points line `index` shows, its segments one after the other.
    static QList<QPointF> shown(const TrendChart& chart, int index)
    {
        QList<QPointF> all;
        for (const QList<QPointF>& part : chart.lines().lines().value(index).drawn)
            all << part;
        return all;
    }

    static QDateTimeAxis* timeAxis(TrendChart& chart)
    {
        return qobject_cast<QDateTimeAxis*>(chart.chart()->axes(Qt::Horizontal).value(0));
    }

    static QString valueAxisTitle(TrendChart& chart, int index)
    {
        const auto axes = chart.chart()->axes(Qt::Vertical, line(chart, index));
        return axes.isEmpty() ? QString() : axes.first()->titleText();
    }

    void mouse(QWidget* viewport, QEvent::Type type, double x, double y)
    {
        const QPointF pos(x, y);
        QMouseEvent event(type, pos, viewport->mapToGlobal(pos), Qt::LeftButton,
                          type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::LeftButton,
                          Qt::NoModifier);
        QCoreApplication::sendEvent(viewport, &event);
    }
};

} // namespace

TEST_F(TrendChartTest, SpeedOfAStartedDriveRampsUpInTheChart)
{
    auto chart = makeChart({{1, kSpeed}});
    EXPECT_TRUE(hub->isWatched(1));
    ASSERT_TRUE(waitUntil([&] { return pointCount(1, "status.current_speed") >= 3; }));
    startMotor(1);
    ASSERT_TRUE(waitUntil([&] { return lastValue(1, "status.current_speed") >= 2900; }, 8000));
    chart->refresh();
    QLineSeries* s = line(*chart, 0);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->name(), QStringLiteral("1 DBU200 Current speed"));
    const QList<QPointF> points = shown(*chart, 0);
    ASSERT_GE(points.size(), 5);
    // The legend's series holds no points: QtCharts would lay out and stroke them all again
    // on every redraw; TrendCanvas draws them.
    EXPECT_EQ(s->count(), 0);
    int rising = 0;
    for (int i = 1; i < points.size(); ++i) {
        EXPECT_GE(points[i].x(), points[i - 1].x());
        rising += points[i].y() > points[i - 1].y() ? 1 : 0;
    }
    EXPECT_GE(rising, 3); // a ramp over about a second, polled every 50 ms
    EXPECT_LT(points.first().y(), 100);
    EXPECT_GE(points.last().y(), 2900);
    EXPECT_TRUE(valueAxisTitle(*chart, 0).contains(QStringLiteral("r/min")))
        << qPrintable(valueAxisTitle(*chart, 0));
    EXPECT_TRUE(valueAxisTitle(*chart, 0).contains(QStringLiteral("Current speed")));
    // A short chart (a laptop's monitor page) still shows every value label whole, never "...".
    chart->resize(630, 170);
    QTest::qWait(200);
    for (QAbstractAxis* axis : chart->chart()->axes(Qt::Vertical))
        EXPECT_FALSE(axis->labelsTruncated()) << qPrintable(axis->titleText());
    chart->hide();
    EXPECT_FALSE(hub->isWatched(1)); // watched only while shown
}

TEST_F(TrendChartTest, TwoDrivesGetSeriesNamedAfterTheDriveAndAnAxisPerUnit)
{
    auto chart = makeChart({{1, kSpeed}, {2, kSpeed}, {2, kLoad}});
    EXPECT_TRUE(hub->isWatched(1));
    EXPECT_TRUE(hub->isWatched(2));
    ASSERT_TRUE(waitUntil([&] {
        return pointCount(1, "status.current_speed") >= 2 && pointCount(2, "status.load") >= 2;
    }));
    chart->refresh();
    ASSERT_EQ(chart->chart()->series().size(), 3);
    EXPECT_EQ(line(*chart, 0)->name(), QStringLiteral("1 DBU200 Current speed"));
    EXPECT_EQ(line(*chart, 1)->name(), QStringLiteral("2 DBU200 Current speed"));
    EXPECT_EQ(line(*chart, 2)->name(), QStringLiteral("2 DBU200 Load rate"));
    EXPECT_FALSE(shown(*chart, 1).isEmpty());
    EXPECT_TRUE(valueAxisTitle(*chart, 1).contains(QStringLiteral("[r/min]")));
    EXPECT_TRUE(valueAxisTitle(*chart, 2).contains(QStringLiteral("[%]")))
        << qPrintable(valueAxisTitle(*chart, 2));
    EXPECT_NE(line(*chart, 0)->pen().color(), line(*chart, 1)->pen().color());
    // One drive's quantities differ by colour, not only by dash; the drives by dash too.
    EXPECT_NE(line(*chart, 1)->pen().color(), line(*chart, 2)->pen().color());
    EXPECT_EQ(line(*chart, 1)->pen().style(), line(*chart, 2)->pen().style());
    EXPECT_NE(line(*chart, 0)->pen().style(), line(*chart, 1)->pen().style());

    DeviceInfo info = drives->info(2);
    info.model = QStringLiteral("DBU400");
    drives->update(info);
    EXPECT_EQ(line(*chart, 1)->name(), QStringLiteral("2 DBU400 Current speed"));

    chart->setSources({{2, kSpeed}});
    EXPECT_FALSE(hub->isWatched(1));
    EXPECT_TRUE(hub->isWatched(2));
}

TEST_F(TrendChartTest, PauseFreezesTheViewWhileHistoryGrowsAndResetZoomFollowsAgain)
{
    auto chart = makeChart({{1, kSpeed}});
    ASSERT_TRUE(waitUntil([&] { return pointCount(1, "status.current_speed") >= 3; }));
    int paused = 0;
    QObject::connect(chart.get(), &TrendChart::pausedChanged, chart.get(), [&] { ++paused; });
    chart->setPaused(true);
    EXPECT_TRUE(chart->isPaused());
    EXPECT_FALSE(chart->isFollowing());
    EXPECT_EQ(paused, 1);
    const QDateTime min = timeAxis(*chart)->min();
    const QDateTime max = timeAxis(*chart)->max();
    const int before = pointCount(1, "status.current_speed");
    waitUntil([] { return false; }, 600);
    EXPECT_GT(pointCount(1, "status.current_speed"), before + 3);
    EXPECT_EQ(timeAxis(*chart)->min(), min);
    EXPECT_EQ(timeAxis(*chart)->max(), max);

    chart->resetZoom();
    EXPECT_FALSE(chart->isPaused());
    EXPECT_TRUE(chart->isFollowing());
    EXPECT_EQ(paused, 2);
    waitUntil([] { return false; }, 400);
    EXPECT_GT(timeAxis(*chart)->max(), max);
    EXPECT_EQ(timeAxis(*chart)->min().msecsTo(timeAxis(*chart)->max()), 60000);

    // A zoom stops following, too.
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    chart->zoomTo(now - 5000, now - 2000);
    EXPECT_FALSE(chart->isFollowing());
    EXPECT_EQ(timeAxis(*chart)->min().toMSecsSinceEpoch(), now - 5000);
    waitUntil([] { return false; }, 300);
    EXPECT_EQ(timeAxis(*chart)->max().toMSecsSinceEpoch(), now - 2000);
    chart->setWindowSeconds(30);
    chart->resetZoom();
    EXPECT_EQ(timeAxis(*chart)->min().msecsTo(timeAxis(*chart)->max()), 30000);
}

TEST_F(TrendChartTest, MarkersShowTimeAndValueDifferencesWithUnits)
{
    auto chart = makeChart({{1, kSpeed}, {1, kLoad}});
    EXPECT_EQ(chart->markerText(),
              QStringLiteral("Markers: click in the chart to set marker A, click again to set "
                             "marker B."));
    ASSERT_TRUE(waitUntil([&] { return pointCount(1, "status.current_speed") >= 3; }));
    startMotor(1);
    ASSERT_TRUE(waitUntil([&] { return lastValue(1, "status.current_speed") >= 2900; }, 8000));
    const TrendHistory::Series* speed = series(1, "status.current_speed");
    const qint64 a = speed->points[1].ms + 10;
    const qint64 b = speed->points.last().ms + 5;
    int changes = 0;
    QObject::connect(chart.get(), &TrendChart::markersChanged, chart.get(), [&] { ++changes; });
    chart->setMarker(0, a);
    chart->setMarker(1, b);
    EXPECT_EQ(changes, 2);
    double va = 0;
    double vb = 0;
    ASSERT_TRUE(TrendHistory::valueAt(*speed, a, &va));
    ASSERT_TRUE(TrendHistory::valueAt(*speed, b, &vb));
    const QString text = chart->markerText();
    EXPECT_TRUE(text.contains(
        QStringLiteral("Δt = B − A = %1 s").arg(QString::number((b - a) / 1000.0, 'f', 3))))
        << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("1 DBU200 Current speed:   A %1 r/min   B %2 r/min   "
                                             "Δ +%3 r/min")
                                  .arg(va)
                                  .arg(vb)
                                  .arg(vb - va)))
        << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("1 DBU200 Load rate:   A ")));
    EXPECT_EQ(chart->findChild<QLabel*>(QStringLiteral("markerReadout"))->text(), text);
    chart->clearMarkers();
    EXPECT_FALSE(chart->marker(0));
    EXPECT_EQ(changes, 3);

    // Clicking places A, then B; a drag zooms the time axis.
    chart->setPaused(true);
    auto* view = chart->findChild<TrendChartView*>();
    ASSERT_TRUE(view);
    const QRectF plot = chart->chart()->plotArea();
    const double y = plot.center().y();
    const double x1 = plot.left() + plot.width() * 0.25;
    const double x2 = plot.left() + plot.width() * 0.75;
    mouse(view->viewport(), QEvent::MouseButtonPress, x1, y);
    mouse(view->viewport(), QEvent::MouseButtonRelease, x1, y);
    mouse(view->viewport(), QEvent::MouseButtonPress, x2, y);
    mouse(view->viewport(), QEvent::MouseButtonRelease, x2, y);
    ASSERT_TRUE(chart->marker(0) && chart->marker(1));
    const qint64 quarter = (chart->viewTo() - chart->viewFrom()) / 4;
    EXPECT_NEAR(double(*chart->marker(0)), double(chart->viewFrom() + quarter), 500.0);
    EXPECT_NEAR(double(*chart->marker(1)), double(chart->viewTo() - quarter), 500.0);
    const qint64 span = chart->viewTo() - chart->viewFrom();
    chart->setPaused(false);
    mouse(view->viewport(), QEvent::MouseButtonPress, x1, y);
    mouse(view->viewport(), QEvent::MouseMove, x2, y);
    mouse(view->viewport(), QEvent::MouseButtonRelease, x2, y);
    EXPECT_FALSE(chart->isFollowing());
    EXPECT_NEAR(double(chart->viewTo() - chart->viewFrom()), span / 2.0, span / 50.0);
    // The wheel zooms in around the cursor.
    const qint64 zoomed = chart->viewTo() - chart->viewFrom();
    const QPointF at(plot.center().x(), y);
    QWheelEvent wheel(at, view->viewport()->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(view->viewport(), &wheel);
    EXPECT_NEAR(double(chart->viewTo() - chart->viewFrom()), zoomed * 0.8, zoomed / 50.0);
    chart->resetZoom();
    EXPECT_TRUE(chart->isFollowing());
}

TEST_F(TrendChartTest, ExportsTheVisibleRangeAsCsvAndPng)
{
    auto chart = makeChart({{1, kSpeed}});
    QTemporaryDir dir;
    QString error;
    EXPECT_FALSE(chart->exportCsv(dir.filePath(QStringLiteral("empty.csv")), &error));
    EXPECT_FALSE(error.isEmpty());
    ASSERT_TRUE(waitUntil([&] { return pointCount(1, "status.current_speed") >= 5; }));
    chart->setPaused(true);
    const QString csv = dir.filePath(QStringLiteral("trend.csv"));
    ASSERT_TRUE(chart->exportCsv(csv, &error)) << qPrintable(error);
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QStringList lines =
        QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_FALSE(lines.isEmpty());
    EXPECT_EQ(lines.first(), QStringLiteral("time,seconds,1 DBU200 Current speed [r/min]"));
    const TrendHistory::Series* s = series(1, "status.current_speed");
    const int inRange = TrendHistory::lowerBound(*s, chart->viewTo() + 1) -
                        TrendHistory::lowerBound(*s, chart->viewFrom());
    EXPECT_GE(inRange, 5);
    EXPECT_EQ(lines.size() - 1, inRange);

    const QString png = dir.filePath(QStringLiteral("trend.png"));
    ASSERT_TRUE(chart->exportPng(png, &error)) << qPrintable(error);
    const QImage image(png);
    EXPECT_FALSE(image.isNull());
    EXPECT_GT(image.width(), 100);
    EXPECT_GT(image.height(), 100);
    EXPECT_FALSE(chart->exportPng(dir.filePath(QStringLiteral("missing/dir/x.png")), &error));
}

TEST_F(TrendChartTest, TheLinesAreDrawnInTheirPensColoursInThePlotArea)
{
    auto chart = makeChart({{1, kSpeed}});
    startMotor(1);
    ASSERT_TRUE(waitUntil([&] { return lastValue(1, "status.current_speed") >= 2900; }, 8000));
    chart->refresh();
    const QColor colour = line(*chart, 0)->pen().color();
    const QImage picture = chart->grab().toImage();
    const QRectF plot = chart->chart()->plotArea();
    int drawn = 0;
    for (int y = int(plot.top()); y < int(plot.bottom()); ++y) {
        for (int x = int(plot.left()); x < int(plot.right()); ++x)
            drawn += picture.pixelColor(x, y) == colour ? 1 : 0;
    }
    // The ramp and the held speed: a line tens of pixels long, two wide.
    EXPECT_GT(drawn, 40);
}
