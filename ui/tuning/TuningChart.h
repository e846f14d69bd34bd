#pragma once

#include "ui/tuning/TuningRun.h"

#include <QChartView>
#include <QVector>

class QValueAxis;

namespace opentop {

// The tuning page's plot: command (dotted), speed (solid; a prediction dashed) and load current
// (dash-dot, right axis) against time since the step, every shown run in its own colour.
class TuningChart : public QChartView
{
    Q_OBJECT
public:
    explicit TuningChart(QWidget* parent = nullptr);

    void setSpeedUnit(const QString& unit);
    // Draws these runs (the visible ones) again from their samples.
    void setRuns(const QVector<const TuningRun*>& runs);
    // The drawn curves (tests).
    int curveCount() const;

private:
    // The axes' titles, or their units alone where the plot is too short for them (a laptop
    // with docks open): never elided to "S…".
    void fitTitles();

    QString m_speedUnit;
    QValueAxis* m_time;
    QValueAxis* m_speed;
    QValueAxis* m_current;
};

} // namespace opentop
