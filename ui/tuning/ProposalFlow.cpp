#include "ui/tuning/ProposalFlow.h"

#include "ui/tuning/TuningGains.h"

#include <QAbstractButton>
#include <QMessageBox>
#include <QWidget>

namespace opentop {

ProposalFlow::ProposalFlow(QWidget* page, const QString& drive, TuningGains* gains)
    : QObject(page)
    , m_page(page)
    , m_drive(drive)
    , m_gains(gains)
{
}

void ProposalFlow::propose(const TuningRunner::Result& autotune, double from, double to)
{
    m_proposal = autotune;
    m_proposal->from = from;
    m_proposal->to = to;
    m_checking = false;
    m_verdict.reset();
    emit changed();
}

void ProposalFlow::clear()
{
    m_proposal.reset();
    m_checking = false;
    m_verdict.reset();
    emit changed();
}

void ProposalFlow::accept(const std::function<void()>& runCheck)
{
    if (!m_proposal)
        return;
    const PidGains before = m_gains->present().value_or(m_proposal->gains);
    m_gains->accept(m_proposal->proposal, before, [this, runCheck](bool ok) {
        if (!ok)
            return;
        m_checking = true;
        m_verdict.reset();
        emit changed();
        runCheck();
    });
}

void ProposalFlow::reject()
{
    clear();
    if (!m_gains->isChanged()) {
        m_gains->restore(QString());
        emit message(tr("Proposal rejected; the drive's gains were not changed."), false);
        return;
    }
    m_gains->restore(tr("Proposal rejected"));
}

bool ProposalFlow::judge(const TuningRunner::Result& step)
{
    if (!m_proposal || !m_checking || !m_gains->isAccepted() || step.from != m_proposal->from ||
        step.to != m_proposal->to)
        return false;
    m_verdict = TuningVerdict::judge(step, m_proposal->predictedMetrics);
    emit changed();
    if (!m_verdict->passed)
        emit message(tr("The accepted gains failed the check: %1. Reject them, or store them "
                        "only after looking at the step.")
                         .arg(m_verdict->findings.join(QStringLiteral("; "))),
                     true);
    return true;
}

void ProposalFlow::store()
{
    if (m_verdict && m_verdict->passed) {
        m_gains->store();
        return;
    }
    const TuningVerdict v =
        m_verdict ? *m_verdict : TuningVerdict::notMeasured(tr("no step test ran after Accept"));
    auto* box = new QMessageBox(
        QMessageBox::Warning, tr("Store gains that failed the check?"),
        tr("The gains accepted on %1 did not pass the check after Accept.").arg(m_drive) +
            QStringLiteral("\n\n") + v.text() + QStringLiteral("\n\n") +
            tr("Stored, they stay after a power cycle and the motor may oscillate or overshoot "
               "as measured. Reject writes back the gains the drive had."),
        QMessageBox::No | QMessageBox::Yes | QMessageBox::Cancel, m_page);
    box->setObjectName(QStringLiteral("storeQuestion"));
    box->setTextFormat(Qt::PlainText); // names the drive
    box->button(QMessageBox::No)->setText(tr("Reject the gains"));
    box->button(QMessageBox::Yes)->setText(tr("Store anyway"));
    box->setDefaultButton(QMessageBox::No);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::ApplicationModal);
    connect(box, &QMessageBox::buttonClicked, this, [this, box](QAbstractButton* b) {
        const QMessageBox::StandardButton picked = box->standardButton(b);
        if (picked == QMessageBox::Yes)
            m_gains->store();
        else if (picked == QMessageBox::No)
            reject();
    });
    box->show();
}

} // namespace opentop
