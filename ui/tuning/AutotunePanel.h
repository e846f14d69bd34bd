#pragma once

#include "model/tuning/TuningRunner.h"
#include "model/tuning/TuningVerdict.h"

#include <QWidget>
#include <optional>

class QComboBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QPushButton;

namespace opentop {

// The relay autotune's side of the tuning page: operating speed, relay amplitude and the rule;
// after a run the ultimate gain and period, the fitted model and the proposed gains next to
// the present ones, with Accept, Reject and Store. Only asks: the page runs the tests.
class AutotunePanel : public QWidget
{
    Q_OBJECT
public:
    explicit AutotunePanel(const TuningSpec& spec, QWidget* parent = nullptr);

    // The closed-loop speed unit and its raw scale (engineering per register count).
    void setSpeedUnit(const QString& unit, double feedbackScale);
    // The plan of the fields, or nothing and *error.
    std::optional<TuningRunner::RelayPlan> plan(QString* error) const;
    double speed() const;

    void setPresentGains(const std::optional<PidGains>& gains);
    void showResult(const TuningRunner::Result& result);
    void clearResult();
    // The check after Accept (none: not run yet).
    void setVerdict(const std::optional<TuningVerdict>& verdict);
    // What may be clicked: nothing while busy; Accept and Reject with a proposal; Store after
    // an accept.
    void setState(bool busy, bool proposal, bool accepted);
    QString resultText() const; // Ku, Tu and the model (tests)
    QString proposalText() const;
    QString verdictText() const;

signals:
    void autotuneClicked();
    void acceptClicked();
    void rejectClicked();
    void storeClicked();

private:
    void showGains(int column, const std::optional<PidGains>& gains);

    TuningSpec m_spec;
    QString m_unit;
    double m_scale = 1;
    QLineEdit* m_speed;
    QLineEdit* m_amplitude;
    QComboBox* m_rule;
    QLabel* m_speedUnit;
    QPushButton* m_autotune;
    QLabel* m_result;
    QLabel* m_verdict;
    QGridLayout* m_gains;
    QPushButton* m_accept;
    QPushButton* m_reject;
    QPushButton* m_store;
    std::optional<PidGains> m_proposal;
};

} // namespace opentop
