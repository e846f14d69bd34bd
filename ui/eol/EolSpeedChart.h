#pragma once

#include <QHash>
#include <QWidget>

class QChart;
class QLineSeries;
class QValueAxis;
class QChartView;

namespace opentop {

// The live speed of each drive of the unit under test, from the run's own samples (nothing
// else polls the drives meanwhile). Cleared when the next unit starts.
class EolSpeedChart : public QWidget
{
    Q_OBJECT
public:
    explicit EolSpeedChart(QWidget* parent = nullptr);

    void clear();
    void add(int machineNumber, double seconds, double speed, const QString& unit);
    int pointCount() const;

private:
    QChart* m_chart;
    QChartView* m_view;
    QValueAxis* m_time;
    QValueAxis* m_speed;
    QHash<int, QLineSeries*> m_series;
    QString m_unit; // the speed unit of the last unit tested
    double m_maxSpeed = 0;
};

} // namespace opentop
