#pragma once

#include "model/monitor/MonitorHub.h"
#include "ui/trends/TrendAxes.h"
#include "ui/trends/TrendLines.h"

#include <QPointer>
#include <QTimer>
#include <QVector>
#include <QWidget>
#include <array>
#include <optional>

class QChart;
class QDateTimeAxis;
class QLabel;

namespace opentop {

class BusDrives;
class TrendCanvas;
class TrendChartView;

// A live trend chart of monitor quantities from a MonitorHub: a scrolling time axis, one value
// axis per unit, zoom, pause, markers A and B with a read-out of the values and their
// differences, export. Redraws at a few hertz from the hub's histories, visible window only, so
// that many drives polled fast stay cheap.
class TrendChart : public QWidget
{
    Q_OBJECT
public:
    explicit TrendChart(MonitorHub* hub, QWidget* parent = nullptr);
    ~TrendChart() override;

    // The series shown; their drives are watched in the hub while the chart is shown.
    void setSources(const QVector<TrendSource>& sources);
    QVector<TrendSource> sources() const;
    // Visible time span while following live data.
    void setWindowSeconds(int seconds);
    int windowSeconds() const { return m_windowMs / 1000; }
    // Freezes the view; the hub keeps collecting.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Back to following live data (also ends a pause).
    void resetZoom();
    // Whether the time axis follows live data (false after a zoom).
    bool isFollowing() const { return m_following && !m_paused; }
    // Shows [fromMs, toMs] and stops following.
    void zoomTo(qint64 fromMs, qint64 toMs);
    qint64 viewFrom() const { return m_from; }
    qint64 viewTo() const { return m_to; }

    // CSV of the visible time range.
    bool exportCsv(const QString& path, QString* error) const;
    bool exportPng(const QString& path, QString* error);

    // The read-out shown under the chart.
    QString markerText() const;
    void setMarker(int index /*0 = A, 1 = B*/, qint64 ms);
    void clearMarkers();
    std::optional<qint64> marker(int index) const;

    // "1 DBU200": how a drive is named in series names and exports.
    static QString driveTitle(const BusDrives* drives, int slave);
    QString seriesName(const TrendSource& source) const;
    QChart* chart() const { return m_chart; }
    // The lines and the points each shows (TrendCanvas draws them; the series hold none).
    const TrendLines& lines() const { return m_lines; }
    // Redraws now; a timer calls it a few times a second.
    void refresh();

signals:
    void pausedChanged(bool paused);
    void followingChanged(bool following);
    void markersChanged();

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    BusDrives* drives() const { return m_hub ? m_hub->drives() : nullptr; }
    void rebuild(); // the lines on the chart, named by seriesName()
    void watch(bool on);
    void updateReadout();
    void placeMarker(qint64 ms);
    void zoomAround(qint64 centerMs, double factor);
    void setFollowing(bool following);

    QPointer<MonitorHub> m_hub; // the chart may outlive it while a window closes
    QChart* m_chart;
    TrendChartView* m_view;
    QLabel* m_readout;
    QDateTimeAxis* m_timeAxis;
    TrendAxes m_axes;
    TrendLines m_lines;
    TrendCanvas* m_canvas; // owned by m_chart
    QTimer m_timer;
    int m_windowMs = 60000;
    bool m_paused = false;
    bool m_following = true;
    bool m_watching = false;
    qint64 m_from = 0;
    qint64 m_to = 0;
    std::array<std::optional<qint64>, 2> m_markers;
    int m_nextMarker = 0;
};

} // namespace opentop
