#pragma once

#include "model/tuning/TuningRunner.h"

#include <QWidget>
#include <optional>

class QLabel;
class QLineEdit;
class QPushButton;

namespace opentop {

// The step test's fields on the tuning page: from, to (in the closed-loop mode's unit) and the
// record time, the Run button, and a note when the drive is not in a closed-loop mode.
class StepTestPanel : public QWidget
{
    Q_OBJECT
public:
    explicit StepTestPanel(QWidget* parent = nullptr);

    void setSpeedUnit(const QString& unit);
    void setStep(double from, double to);
    void setModeNote(const QString& note);
    void setBusy(bool busy);
    // The larger of the two speeds (0 when not numbers).
    double highestSpeed() const;
    std::optional<TuningRunner::StepPlan> plan(QString* error) const;

signals:
    void runClicked();
    void stepChanged();

private:
    QLineEdit* m_from;
    QLineEdit* m_to;
    QLineEdit* m_record;
    QLabel* m_fromUnit;
    QLabel* m_toUnit;
    QLabel* m_note;
    QPushButton* m_run;
    QString m_unit;
};

} // namespace opentop
