#include "ui/tuning/TuningPage.h"

#include "model/session/DeviceSession.h"
#include "ui/tuning/AutotunePanel.h"
#include "ui/tuning/NumberField.h"
#include "ui/tuning/ProposalFlow.h"
#include "ui/tuning/StepTestPanel.h"
#include "ui/tuning/TuningDriveSettings.h"
#include "ui/tuning/TuningGains.h"
#include "ui/tuning/TuningLimitsBox.h"
#include "ui/tuning/TuningRunsView.h"
#include "ui/tuning/TuningStatusRow.h"
#include "ui/widgets/ConfirmBox.h"

#include <QHBoxLayout>
#include <QPointer>
#include <QScrollArea>
#include <QStyle>
#include <QTabWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace opentop {

namespace {

QString n(double v)
{
    return NumberField::text(v);
}

} // namespace

TuningPage::TuningPage(DeviceSession* session, const TuningSpec& spec, const QString& drive,
                       QWidget* parent)
    : QWidget(parent)
    , m_session(session)
    , m_spec(spec)
    , m_drive(drive)
    , m_runner(new TuningRunner(session, spec, this))
    , m_gains(new TuningGains(m_runner, this))
    , m_settings(new TuningDriveSettings(session, spec, this))
    , m_status(new TuningStatusRow(this))
    , m_limits(new TuningLimitsBox(this))
    , m_sides(new QTabWidget(this))
    , m_step(new StepTestPanel(this))
    , m_autotune(new AutotunePanel(spec, this))
    , m_runs(new TuningRunsView(drive, this))
    , m_flow(new ProposalFlow(this, drive, m_gains))
{
    setObjectName(QStringLiteral("tuningPage"));
    m_sides->addTab(m_step, tr("Step test"));
    m_sides->addTab(m_autotune, tr("Relay autotune"));
    auto* leftBox = new QWidget(this);
    auto* left = new QVBoxLayout(leftBox);
    left->setContentsMargins(0, 0, 0, 0);
    left->addWidget(m_limits);
    left->addWidget(m_sides, 1);
    // Scrolls rather than raising the window's minimum height (docks open on a laptop).
    auto* leftScroll = new QScrollArea(this);
    leftScroll->setFrameShape(QFrame::NoFrame);
    leftScroll->setWidgetResizable(true);
    leftScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    leftScroll->setWidget(leftBox);
    // Room for the vertical scroll bar beside the fields: a long result must not push them
    // under it.
    const int fields =
        leftBox->minimumSizeHint().width() + style()->pixelMetric(QStyle::PM_ScrollBarExtent);
    leftScroll->setMaximumWidth(std::max(300, fields));
    leftScroll->setMinimumWidth(std::max(260, fields));

    auto* columns = new QHBoxLayout;
    columns->addWidget(leftScroll);
    columns->addWidget(m_runs, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_status);
    layout->addLayout(columns, 1);

    connect(m_status, &TuningStatusRow::stopClicked, this, &TuningPage::stop);
    connect(m_step, &StepTestPanel::runClicked, this, &TuningPage::runStep);
    connect(m_step, &StepTestPanel::stepChanged, this, &TuningPage::updateAutoLimits);
    connect(m_autotune, &AutotunePanel::autotuneClicked, this, &TuningPage::runAutotune);
    // Accept writes the proposal, then offers the step the prediction shows, to compare.
    connect(m_autotune, &AutotunePanel::acceptClicked, this, [this] {
        if (!isBusy())
            m_flow->accept([this] {
                showStepTest();
                runStep(); // asks first
            });
    });
    connect(m_autotune, &AutotunePanel::rejectClicked, this, [this] {
        if (!isBusy())
            m_flow->reject();
    });
    connect(m_autotune, &AutotunePanel::storeClicked, m_flow, &ProposalFlow::store);
    connect(m_flow, &ProposalFlow::changed, this, [this] {
        if (!m_flow->proposal())
            m_autotune->clearResult();
        m_autotune->setVerdict(m_flow->verdict());
        updateState();
    });
    connect(m_flow, &ProposalFlow::message, m_status, &TuningStatusRow::setPhase);
    connect(m_sides, &QTabWidget::currentChanged, this, &TuningPage::updateAutoLimits);
    connect(m_runner, &TuningRunner::phase, this,
            [this](const QString& text) { m_status->setPhase(text); });
    connect(m_runner, &TuningRunner::sampled, m_runs, &TuningRunsView::addLiveSample);
    connect(m_settings, &TuningDriveSettings::changed, this, &TuningPage::settingsRead);
    connect(m_gains, &TuningGains::presentChanged, m_autotune, &AutotunePanel::setPresentGains);
    connect(m_gains, &TuningGains::message, m_status, &TuningStatusRow::setPhase);
    connect(m_gains, &TuningGains::busyChanged, this, &TuningPage::updateState);
    m_status->setPhase(tr("Ready. Nothing moves until you confirm a test."));
    updateState();
}

TuningPage::~TuningPage()
{
    // A test still running goes on to its end without the page: the runner stops the motor.
    if (m_runner->isRunning()) {
        m_runner->setParent(m_session);
        m_runner->cancel();
    }
}

void TuningPage::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (!isBusy())
        readDrive();
}

QString TuningPage::phaseText() const
{
    return m_status->phaseText();
}

QString TuningPage::stopReport() const
{
    return m_status->stopReport();
}

const QVector<TuningRun>& TuningPage::runs() const
{
    return m_runs->runs();
}

bool TuningPage::isBusy() const
{
    return m_testing || m_gains->isBusy();
}

void TuningPage::showStepTest()
{
    m_sides->setCurrentIndex(0);
}

void TuningPage::showAutotune()
{
    m_sides->setCurrentIndex(1);
}

// The speed mode (the unit of a step), the drive's maximum current and its present gains.
void TuningPage::readDrive()
{
    m_settings->read();
    m_gains->refresh();
}

void TuningPage::settingsRead()
{
    const QString unit = m_settings->speedUnit();
    m_step->setModeNote(m_settings->modeNote());
    m_step->setSpeedUnit(unit);
    m_limits->setSpeedUnit(unit);
    m_autotune->setSpeedUnit(unit, m_settings->scale());
    m_runs->setSpeedUnit(unit);
    updateAutoLimits();
}

// Defaults: 125 % of the step's highest speed (room for the overshoot a rule allows), 150 % of
// the relay's operating speed (it oscillates around it), 1.2 × the drive's maximum current.
void TuningPage::updateAutoLimits()
{
    const double speed =
        m_sides->currentIndex() == 0 ? 1.25 * m_step->highestSpeed() : 1.5 * m_autotune->speed();
    m_limits->setDefaults(speed, 1.2 * m_settings->maxCurrent());
}

QString TuningPage::confirmLimits(const TuningRunner::Limits& l) const
{
    return tr("Limits: %1 %2, %3.")
        .arg(n(l.maxSpeed), m_settings->speedUnit(),
             l.maxCurrent > 0 ? tr("%1 A").arg(n(l.maxCurrent)) : tr("no current limit"));
}

void TuningPage::runStep()
{
    updateAutoLimits();
    QString error;
    const std::optional<TuningRunner::StepPlan> plan = m_step->plan(&error);
    const std::optional<TuningRunner::Limits> l =
        plan ? m_limits->limits(m_runner->limits(), &error) : std::nullopt;
    if (!plan || !l) {
        m_status->setPhase(error, true);
        return;
    }
    const QString text =
        tr("The motor of %1 will run from %2 to %3 %4 in its present speed mode, for about "
           "%5 s, and then stop.")
            .arg(m_drive, n(plan->from), n(plan->to), m_settings->speedUnit(),
                 n((plan->recordMs + 1000) / 1000.0)) +
        QStringLiteral("\n\n") + confirmLimits(*l);
    ConfirmBox::ask(this, tr("Step test"), text, tr("Run"),
                    [this, plan = *plan, limits = *l] { startStep(plan, limits); });
}

void TuningPage::runAutotune()
{
    updateAutoLimits();
    QString error;
    const std::optional<TuningRunner::RelayPlan> plan = m_autotune->plan(&error);
    const std::optional<TuningRunner::Limits> l =
        plan ? m_limits->limits(m_runner->limits(), &error) : std::nullopt;
    if (!plan || !l) {
        m_status->setPhase(error, true);
        return;
    }
    const QString text =
        tr("The motor of %1 will run in open loop (the speed loop off) around %2 %3, its output "
           "switching by ±%4 %, for up to %5 s, and then stop.")
            .arg(m_drive, n(plan->speed), m_settings->speedUnit(), n(plan->amplitude),
                 n(plan->maxMs / 1000.0)) +
        QStringLiteral("\n\n") + confirmLimits(*l);
    ConfirmBox::ask(this, tr("Relay autotune"), text, tr("Run"),
                    [this, plan = *plan, limits = *l] { startAutotune(plan, limits); });
}

void TuningPage::stop()
{
    if (m_runner->isRunning()) {
        cancelTest();
        return;
    }
    // Nothing of the page runs: the stop command all the same.
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    options.verify = false;
    const QPointer<TuningPage> self(this);
    m_session->write(
        m_spec.command, QStringLiteral("0"), options, [self](const DeviceSession::Outcome& o) {
            if (self)
                self->m_status->setPhase(o.ok ? tr("Stop command sent.")
                                              : tr("Stop command failed: %1").arg(o.error),
                                         !o.ok);
        });
}

void TuningPage::cancelTest()
{
    if (!m_runner->isRunning())
        return;
    m_cancelled = true;
    m_status->setPhase(tr("Stopping…"), true);
    m_runner->cancel();
}

void TuningPage::startStep(const TuningRunner::StepPlan& plan, const TuningRunner::Limits& limits)
{
    if (isBusy())
        return;
    m_testing = true;
    m_cancelled = false;
    m_status->clearStopReport();
    m_runner->setLimits(limits);
    const QString unit = m_settings->speedUnit();
    m_runs->beginLive(
        tr("Run %1: %2 → %3 %4").arg(m_runs->nextId()).arg(n(plan.from), n(plan.to), unit),
        m_gains->present().value_or(PidGains()), plan.from, plan.to, unit);
    updateState();
    const QPointer<TuningPage> self(this);
    TuningRunner* runner = m_runner;
    m_runner->startStep(plan, [self, runner](const TuningRunner::Result& r) {
        if (!self) {
            runner->deleteLater();
            return;
        }
        self->stepDone(r);
    });
}

void TuningPage::stepDone(const TuningRunner::Result& result)
{
    m_testing = false;
    m_runs->endLive(result, m_settings->speedUnit());
    m_status->showStopReport(result);
    m_status->setPhase(result.ok ? tr("Step test done.")
                                 : tr("Step test ended: %1").arg(result.error),
                       !result.ok);
    m_flow->judge(result); // the check after Accept: says so when it fails
    // Stopped by the user: the gains the page changed go back (a limit leaves them, to see).
    if (result.aborted && m_cancelled && m_gains->isChanged())
        m_gains->restore(tr("The test was stopped"));
    updateState();
}

void TuningPage::startAutotune(const TuningRunner::RelayPlan& plan,
                               const TuningRunner::Limits& limits)
{
    if (isBusy())
        return;
    m_testing = true;
    m_cancelled = false;
    m_status->clearStopReport();
    m_runner->setLimits(limits);
    m_flow->clear();
    const QPointer<TuningPage> self(this);
    TuningRunner* runner = m_runner;
    m_runner->startAutotune(plan, [self, runner](const TuningRunner::Result& r) {
        if (!self) {
            runner->deleteLater();
            return;
        }
        self->autotuneDone(r);
    });
}

void TuningPage::autotuneDone(const TuningRunner::Result& result)
{
    m_testing = false;
    m_status->showStopReport(result);
    m_autotune->showResult(result);
    if (!result.ok) {
        m_status->setPhase(tr("Autotune ended: %1").arg(result.error), true);
        if (result.aborted && m_cancelled && m_gains->isChanged())
            m_gains->restore(tr("The autotune was stopped"));
        updateState();
        return;
    }
    // The runner predicts the step from half the operating speed to it.
    const double to = m_autotune->speed();
    const double from = to / 2;
    m_flow->propose(result, from, to);
    const QString unit = m_settings->speedUnit();
    m_runs->addPrediction(tr("Predicted: %1 → %2 %3").arg(n(from), n(to), unit), result, from, to,
                          unit);
    m_step->setStep(from, to);
    m_status->setPhase(tr("Autotune done: proposal %1. Accept writes it to the drive.")
                           .arg(result.proposal.toString()));
    updateState();
}

void TuningPage::updateState()
{
    const bool busy = isBusy();
    m_step->setBusy(busy);
    m_autotune->setState(busy, m_flow->proposal().has_value(), m_gains->isAccepted());
}

} // namespace opentop
