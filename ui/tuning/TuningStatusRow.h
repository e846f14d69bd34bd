#pragma once

#include "model/tuning/TuningRunner.h"

#include <QWidget>

class QLabel;
class QPushButton;

namespace opentop {

// The tuning page's top row, always in view: the red STOP, what runs now (the phase, red when
// something went wrong) and how the last test stopped (red and bold unless the stop was
// confirmed). Only shows: the page decides what STOP does.
class TuningStatusRow : public QWidget
{
    Q_OBJECT
public:
    explicit TuningStatusRow(QWidget* parent = nullptr);

    void setPhase(const QString& text, bool bad = false);
    void showStopReport(const TuningRunner::Result& result);
    void clearStopReport();
    QString phaseText() const;
    QString stopReport() const;

signals:
    void stopClicked();

private:
    QPushButton* m_stop;
    QLabel* m_phase;
    QLabel* m_stopReport;
};

} // namespace opentop
