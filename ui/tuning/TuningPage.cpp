#include "ui/tuning/TuningPage.h"

#include "model/session/DeviceSession.h"
#include "ui/tuning/AutotunePanel.h"
#include "ui/tuning/NumberField.h"
#include "ui/tuning/ProposalFlow.h"
#include "ui/tuning/StepTestPanel.h"
#include "ui/tuning/TuningGains.h"
#include "ui/tuning/TuningLimitsBox.h"
#include "ui/tuning/TuningRunsView.h"
#include "ui/widgets/ConfirmBox.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
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
    , m_stop(new QPushButton(tr("STOP"), this))
    , m_phase(new QLabel(this))
    , m_stopReport(new QLabel(this))
    , m_limits(new TuningLimitsBox(this))
    , m_sides(new QTabWidget(this))
    , m_step(new StepTestPanel(this))
    , m_autotune(new AutotunePanel(spec, this))
    , m_runs(new TuningRunsView(drive, this))
    , m_flow(new ProposalFlow(this, drive, m_gains))
{
    setObjectName(QStringLiteral("tuningPage"));
    m_stop->setObjectName(QStringLiteral("tuningStop"));
    m_stop->setToolTip(tr("Cancels the running test: the motor is stopped and the stop confirmed"));
    m_stop->setStyleSheet(QStringLiteral("QPushButton { background: #c0392b; color: white; "
                                         "font-weight: bold; padding: 6px 18px; }"));
    m_phase->setObjectName(QStringLiteral("tuningPhase"));
    m_stopReport->setObjectName(QStringLiteral("stopReport"));
    m_phase->setWordWrap(true);
    m_stopReport->setWordWrap(true);

    // STOP, what runs now and how the last test stopped: always in view.
    auto* top = new QHBoxLayout;
    top->addWidget(m_stop);
    auto* status = new QVBoxLayout;
    status->addWidget(m_phase);
    status->addWidget(m_stopReport);
    top->addLayout(status, 1);

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
    layout->addLayout(top);
    layout->addLayout(columns, 1);

    connect(m_stop, &QPushButton::clicked, this, &TuningPage::stop);
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
    connect(m_flow, &ProposalFlow::message, this, &TuningPage::setPhase);
    connect(m_sides, &QTabWidget::currentChanged, this, &TuningPage::updateAutoLimits);
    connect(m_runner, &TuningRunner::phase, this, [this](const QString& text) { setPhase(text); });
    connect(m_runner, &TuningRunner::sampled, this, [this](const TuningSample& s) {
        if (TuningRun* run = m_runs->run(m_liveId))
            run->result.samples << s;
    });
    connect(m_gains, &TuningGains::presentChanged, m_autotune, &AutotunePanel::setPresentGains);
    connect(m_gains, &TuningGains::message, this, &TuningPage::setPhase);
    connect(m_gains, &TuningGains::busyChanged, this, &TuningPage::updateState);
    setPhase(tr("Ready. Nothing moves until you confirm a test."));
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
    return m_phase->text();
}

QString TuningPage::stopReport() const
{
    return m_stopReport->text();
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

void TuningPage::setPhase(const QString& text, bool bad)
{
    m_phase->setText(text);
    m_phase->setStyleSheet(bad ? QStringLiteral("color: #c0392b;") : QString());
}

// The speed mode (the unit of a step), the drive's maximum current and its present gains.
void TuningPage::readDrive()
{
    const QPointer<TuningPage> self(this);
    QStringList names{m_spec.speedMode};
    const QString maxCurrent = QStringLiteral("config.max_current");
    if (m_session->profile().parameter(maxCurrent))
        names << maxCurrent;
    m_session->readMany(names, [self, this, maxCurrent](const DeviceSession::ReadManyOutcome& r) {
        if (!self)
            return;
        const DeviceSession::Outcome mode = r.results.value(m_spec.speedMode);
        const TuningSpec::ClosedLoopMode* loop =
            mode.ok ? m_spec.closedLoop(int(mode.value.raw)) : nullptr;
        const bool closedLoop = loop != nullptr;
        if (!loop && !m_spec.closedLoopModes.isEmpty())
            loop = &m_spec.closedLoopModes.first();
        // The units of the closed-loop mode, also while the drive is in another.
        ValueContext context = m_session->context();
        if (loop) {
            const auto base = context.parameterRaw;
            const QString modeName = m_spec.speedMode;
            const qint64 closed = loop->mode;
            context.parameterRaw = [base, modeName, closed](const QString& p) {
                return p == modeName ? std::optional<qint64>(closed)
                                     : (base ? base(p) : std::nullopt);
            };
            if (const ParameterMeta* meta = m_session->profile().parameter(loop->feedback))
                m_unit = meta->specFor(context).unit;
        }
        if (const ParameterMeta* meta = m_session->profile().parameter(m_spec.command))
            m_scale = meta->specFor(context).scale;
        const DeviceSession::Outcome current = r.results.value(maxCurrent);
        m_maxCurrentSetting = current.ok ? current.value.number : 0;
        m_step->setModeNote(
            !mode.ok ? tr("Could not read the speed mode: %1").arg(mode.error)
            : closedLoop
                ? QString()
                : tr("The drive is not in a closed-loop speed mode (now: %1). Choose "
                     "one on its settings page first.")
                      .arg(mode.value.text.isEmpty() ? n(mode.value.raw) : mode.value.text));
        m_step->setSpeedUnit(m_unit);
        m_limits->setSpeedUnit(m_unit);
        m_autotune->setSpeedUnit(m_unit, m_scale);
        m_runs->setSpeedUnit(m_unit);
        updateAutoLimits();
    });
    m_gains->refresh();
}

// Defaults: 125 % of the step's highest speed (room for the overshoot a rule allows), 150 % of
// the relay's operating speed (it oscillates around it), 1.2 × the drive's maximum current.
void TuningPage::updateAutoLimits()
{
    const double speed =
        m_sides->currentIndex() == 0 ? 1.25 * m_step->highestSpeed() : 1.5 * m_autotune->speed();
    m_limits->setDefaults(speed, 1.2 * m_maxCurrentSetting);
}

QString TuningPage::confirmLimits(const TuningRunner::Limits& l) const
{
    return tr("Limits: %1 %2, %3.")
        .arg(n(l.maxSpeed), m_unit,
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
        setPhase(error, true);
        return;
    }
    const QString text =
        tr("The motor of %1 will run from %2 to %3 %4 in its present speed mode, for about "
           "%5 s, and then stop.")
            .arg(m_drive, n(plan->from), n(plan->to), m_unit, n((plan->recordMs + 1000) / 1000.0)) +
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
        setPhase(error, true);
        return;
    }
    const QString text =
        tr("The motor of %1 will run in open loop (the speed loop off) around %2 %3, its output "
           "switching by ±%4 %, for up to %5 s, and then stop.")
            .arg(m_drive, n(plan->speed), m_unit, n(plan->amplitude), n(plan->maxMs / 1000.0)) +
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
    m_session->write(m_spec.command, QStringLiteral("0"), options,
                     [self](const DeviceSession::Outcome& o) {
                         if (self)
                             self->setPhase(o.ok ? tr("Stop command sent.")
                                                 : tr("Stop command failed: %1").arg(o.error),
                                            !o.ok);
                     });
}

void TuningPage::cancelTest()
{
    if (!m_runner->isRunning())
        return;
    m_cancelled = true;
    setPhase(tr("Stopping…"), true);
    m_runner->cancel();
}

void TuningPage::startStep(const TuningRunner::StepPlan& plan, const TuningRunner::Limits& limits)
{
    if (isBusy())
        return;
    m_testing = true;
    m_cancelled = false;
    m_stopReport->clear();
    m_runner->setLimits(limits);
    TuningRun& run = m_runs->addRun(
        TuningRun::Kind::Step,
        tr("Run %1: %2 → %3 %4").arg(m_runs->nextId()).arg(n(plan.from), n(plan.to), m_unit),
        m_gains->present().value_or(PidGains()));
    run.live = true;
    run.result.from = plan.from;
    run.result.to = plan.to;
    run.result.speedUnit = m_unit;
    m_liveId = run.id;
    m_runs->runChanged(run.id);
    m_runs->setRecording(true);
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
    if (TuningRun* run = m_runs->run(m_liveId)) {
        run->live = false;
        run->result = result;
        run->result.speedUnit = result.speedUnit.isEmpty() ? m_unit : result.speedUnit;
        if (result.ok || !result.samples.isEmpty())
            run->gains = result.gains;
        m_runs->runChanged(run->id);
    }
    m_liveId = -1;
    m_runs->setRecording(false);
    showStopReport(result);
    setPhase(result.ok ? tr("Step test done.") : tr("Step test ended: %1").arg(result.error),
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
    m_stopReport->clear();
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
    showStopReport(result);
    m_autotune->showResult(result);
    if (!result.ok) {
        setPhase(tr("Autotune ended: %1").arg(result.error), true);
        if (result.aborted && m_cancelled && m_gains->isChanged())
            m_gains->restore(tr("The autotune was stopped"));
        updateState();
        return;
    }
    // The runner predicts the step from half the operating speed to it.
    const double to = m_autotune->speed();
    const double from = to / 2;
    m_flow->propose(result, from, to);
    TuningRun& run =
        m_runs->addRun(TuningRun::Kind::Prediction,
                       tr("Predicted: %1 → %2 %3").arg(n(from), n(to), m_unit), result.proposal);
    run.result.samples = result.predicted;
    run.result.from = from;
    run.result.to = to;
    run.result.speedUnit = result.speedUnit.isEmpty() ? m_unit : result.speedUnit;
    run.result.metrics = StepMetrics::measure(result.predicted, from, to);
    m_runs->runChanged(run.id);
    m_step->setStep(from, to);
    setPhase(tr("Autotune done: proposal %1. Accept writes it to the drive.")
                 .arg(result.proposal.toString()));
    updateState();
}

void TuningPage::showStopReport(const TuningRunner::Result& result)
{
    m_stopReport->setText(result.stopDetail);
    m_stopReport->setStyleSheet(
        result.stopConfirmed ? QString() : QStringLiteral("color: #c0392b; font-weight: bold;"));
}

void TuningPage::updateState()
{
    const bool busy = isBusy();
    m_step->setBusy(busy);
    m_autotune->setState(busy, m_flow->proposal().has_value(), m_gains->isAccepted());
}

} // namespace opentop
