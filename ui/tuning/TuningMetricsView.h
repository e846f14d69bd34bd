#pragma once

#include <QWidget>

class QLabel;

namespace opentop {

struct TuningRun;

// What a run's step response shows: rise time, overshoot, settling time (2 %), steady-state
// error and peak current, each with its unit.
class TuningMetricsView : public QWidget
{
    Q_OBJECT
public:
    explicit TuningMetricsView(QWidget* parent = nullptr);

    // The run's metrics (nothing: dashes).
    void showRun(const TuningRun* run);
    // "Rise time 52 ms; overshoot 4.1 %; ..." (tests, the CSV header).
    QString text() const;

private:
    QLabel* m_title;
    QLabel* m_rise;
    QLabel* m_overshoot;
    QLabel* m_settling;
    QLabel* m_error;
    QLabel* m_peak;
};

} // namespace opentop
