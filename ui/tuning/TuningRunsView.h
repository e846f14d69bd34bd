#pragma once

#include "ui/tuning/TuningRun.h"

#include <QVector>
#include <QWidget>

class QPushButton;
class QTimer;

namespace opentop {

class TuningChart;
class TuningMetricsView;
class TuningRunList;

// The tuning page's runs: the chart with every shown run overlaid, the list of runs (colour,
// step, gains, shown or not) and the selected run's metrics, with Save as CSV and PNG. It keeps
// the runs: a step test's recorded live as its samples come, an autotune's predicted step.
class TuningRunsView : public QWidget
{
    Q_OBJECT
public:
    // `drive` names the drive in the CSV header.
    explicit TuningRunsView(const QString& drive, QWidget* parent = nullptr);

    TuningChart* chart() const { return m_chart; }
    TuningRunList* runList() const { return m_runList; }
    TuningMetricsView* metrics() const { return m_metrics; }
    const QVector<TuningRun>& runs() const { return m_runs; }
    TuningRun* run(int id);
    // The selected run, else the last (null: none).
    const TuningRun* selectedRun() const;
    int nextId() const { return m_nextId; }

    void setSpeedUnit(const QString& unit);
    TuningRun& addRun(TuningRun::Kind kind, const QString& title, const PidGains& gains);
    // The run changed (its samples, its end): list and chart follow.
    void runChanged(int id);
    // While a run records, the chart is drawn again a few times a second.
    void setRecording(bool recording);
    // A step test's run, recording (live) until endLive(); from → to in `unit`.
    void beginLive(const QString& title, const PidGains& gains, double from, double to,
                   const QString& unit);
    void addLiveSample(const TuningSample& sample);
    // The live run ended with `result` (`unit` when the result names none); its gains are
    // those the result ran with once it measured anything.
    void endLive(const TuningRunner::Result& result, const QString& unit);
    // The step an autotune's model predicts for its proposal, from → to.
    void addPrediction(const QString& title, const TuningRunner::Result& autotune, double from,
                       double to, const QString& unit);
    void redraw();

    bool saveCsv(const QString& path, QString* error) const;
    bool savePng(const QString& path) const;

private:
    void saveCsvAsked();
    void savePngAsked();

    QString m_drive;
    QVector<TuningRun> m_runs;
    int m_nextId = 1;
    bool m_recording = false;
    int m_liveId = -1; // the run recording, -1: none
    TuningChart* m_chart;
    TuningRunList* m_runList;
    TuningMetricsView* m_metrics;
    QPushButton* m_saveCsv;
    QPushButton* m_savePng;
    QTimer* m_redraw;
};

} // namespace opentop
