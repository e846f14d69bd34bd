#pragma once

#include "model/tuning/TuningRunner.h"
#include "model/tuning/TuningVerdict.h"

#include <QObject>
#include <functional>
#include <optional>

class QWidget;

namespace opentop {

class TuningGains;

// What becomes of an autotune's proposal on the tuning page. Accept writes it (temporary in
// the drive) and runs the check: the step the prediction shows, measured with the accepted
// gains and judged against the prediction (TuningVerdict). Reject writes back the gains the
// drive had. Store goes straight on only after a passed check; otherwise it asks first, naming
// what was measured, with Reject as the default answer.
class ProposalFlow : public QObject
{
    Q_OBJECT
public:
    // `drive` names the drive for people: "drive 7 (DCPID-20A)".
    ProposalFlow(QWidget* page, const QString& drive, TuningGains* gains);

    // A new proposal, predicted for the step from → to.
    void propose(const TuningRunner::Result& autotune, double from, double to);
    void clear();
    const std::optional<TuningRunner::Result>& proposal() const { return m_proposal; }
    const std::optional<TuningVerdict>& verdict() const { return m_verdict; }

    // Writes the proposal, then `runCheck` (which asks before the step test).
    void accept(const std::function<void()>& runCheck);
    void reject();
    // A step test ended: judged when it is the check. Whether it was.
    bool judge(const TuningRunner::Result& step);
    void store();

signals:
    void changed(); // the proposal or the check's verdict
    void message(const QString& text, bool bad);

private:
    QWidget* m_page;
    QString m_drive;
    TuningGains* m_gains;
    std::optional<TuningRunner::Result> m_proposal; // its from and to: the check's step
    bool m_checking = false;                        // accepted: the check's step is due
    std::optional<TuningVerdict> m_verdict;
};

} // namespace opentop
