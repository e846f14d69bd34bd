#include "ui/run/TestRunPanel.h"

#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/run/StartPreview.h"
#include "model/session/DeviceSession.h"
#include "ui/bus/VariantQuestion.h"
#include "ui/run/CommandReadBack.h"
#include "ui/run/DbuRunCommands.h"
#include "ui/run/DcRunCommands.h"
#include "ui/run/MotionPriorityBox.h"
#include "ui/run/RunLiveState.h"
#include "ui/run/SpnoSelector.h"
#include "ui/widgets/ConfirmBox.h"
#include "ui/widgets/DriveHeading.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>
#include <QVBoxLayout>

namespace opentop {

namespace {

const QString kPriority = QStringLiteral("motionPriority");
const QString kIoPriority = QStringLiteral("ioPriority");
const QString kSpeedCommand = QStringLiteral("speedCommand");
const QString kCommLoss = QStringLiteral("config.comm_loss_time");
constexpr int kSettleMs = 200; // drives update their status within a few cycles of a command

} // namespace

QSet<int> TestRunPanel::s_confirmed;

TestRunPanel::TestRunPanel(BusDrives* drives, int slave, QWidget* parent)
    : QWidget(parent)
    , m_drives(drives)
    , m_slave(slave)
    , m_session(drives->session(slave))
    , m_control(drives->client(), ProfileRegistry::builtIn(), this)
{
    auto* layout = new QVBoxLayout(this);
    // The machine's name as it is now, also when it is given while the page is open.
    layout->addWidget(
        new DriveHeading(drives, slave, tr("<b>Test run of machine number %1</b>"), this));
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // drives' names, the drive's answers
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    if (!m_session) {
        m_message->setText(tr("Machine number %1 has not been identified as a drive of a known "
                              "family; a test run needs one.")
                               .arg(slave));
        layout->addWidget(m_message);
        layout->addStretch();
        return;
    }
    const Profile& profile = m_session->profile();
    m_preview = new StartPreview(drives, this);
    m_isDc =
        RoleEvaluator::parameter(profile, kSpeedCommand) && !profile.role(QStringLiteral("start"));

    // Two columns: the commands first, where a laptop's short window still shows them with a
    // dock open; why the drive refuses them and its live state beside them.
    auto* columns = new QHBoxLayout;
    layout->addLayout(columns, 1);
    auto* left = new QVBoxLayout;
    m_side = new QVBoxLayout;
    columns->addLayout(left, 1);
    columns->addLayout(m_side, 1);

    m_priorityBox = new MotionPriorityBox(drives, m_session, this);
    m_priorityBox->hide();
    connect(m_priorityBox, &MotionPriorityBox::switching, this, [this](const QString& text) {
        m_busy = true;
        updateEnabled();
        setMessage(text, false);
    });
    connect(m_priorityBox, &MotionPriorityBox::switched, this,
            [this](bool ok, const QString& message) {
                m_busy = false;
                setMessage(message, !ok);
                refresh();
            });
    m_side->addWidget(m_priorityBox);
    m_side->addStretch();

    m_commands = new QWidget(this);
    left->addWidget(m_commands);
    if (m_isDc)
        buildDc();
    else
        buildDbu();
    m_warning = new QLabel(this);
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(QStringLiteral("color: #a05000;"));
    m_warning->hide();
    left->addWidget(m_warning);
    left->addWidget(m_message);
    m_state = new CommandReadBack(this);
    left->addWidget(m_state);
    left->addStretch();
    updateEnabled();
    refresh();
}

void TestRunPanel::buildDbu()
{
    auto* column = new QVBoxLayout(m_commands);
    column->setContentsMargins(0, 0, 0, 0);
    m_dbu = new DbuRunCommands(m_session, m_commands);
    m_spno = m_dbu->spnoSelector();
    connect(m_dbu, &DbuRunCommands::commandRequested, this, &TestRunPanel::run);
    connect(m_dbu, &DbuRunCommands::ioPriorityRequested, this,
            [this] { m_priorityBox->askToReturn(this); });
    column->addWidget(m_dbu);
}

void TestRunPanel::buildDc()
{
    auto* column = new QVBoxLayout(m_commands);
    m_dc = new DcRunCommands(m_session, m_commands);
    connect(m_dc, &DcRunCommands::commandRequested, this, &TestRunPanel::run);
    column->addWidget(m_dc);
}

void TestRunPanel::refresh()
{
    if (!m_session)
        return;
    const Profile& profile = m_session->profile();
    QStringList names;
    const ParameterMeta* priority = RoleEvaluator::parameter(profile, kPriority);
    if (priority && priority->isReadable())
        names << priority->name;
    if (const ParameterMeta* speed = RoleEvaluator::parameter(profile, kSpeedCommand))
        names << speed->controllingParameters();
    if (const ParameterMeta* loss = profile.parameter(kCommLoss); loss && loss->isReadable())
        names << loss->name;
    if (m_spno)
        m_spno->refreshLabels();
    if (names.isEmpty()) {
        m_enabled = true;
        updateEnabled();
        emit refreshed();
        return;
    }
    QPointer<TestRunPanel> self(this);
    m_session->readMany(names, [self, priority](const DeviceSession::ReadManyOutcome& o) {
        if (!self)
            return;
        self->m_enabled = true;
        if (priority && priority->isReadable()) {
            const DeviceSession::Outcome r = o.results.value(priority->name);
            if (!r.value.valid) {
                self->m_enabled = false;
                self->m_currentPriority.clear();
                self->setMessage(tr("Cannot read %1 to check that the drive takes motion "
                                    "commands: %2")
                                     .arg(priority->label, r.error),
                                 true);
            } else {
                self->m_currentPriority =
                    ValueCodec::format(*priority, r.value, self->m_session->context());
                self->m_enabled =
                    RoleEvaluator::holds(
                        self->m_session->profile(), kPriority,
                        [&r](const QString&) { return std::optional<double>(r.value.raw); })
                        .value_or(true);
            }
        }
        const DeviceSession::Outcome loss = o.results.value(kCommLoss);
        self->m_commLossSeconds = loss.value.valid ? loss.value.number : 0;
        self->updateEnabled();
        self->updateWarning();
        emit self->refreshed();
    });
}

void TestRunPanel::run(const RunControl::Command& command, bool starts)
{
    if (!starts) {
        send(command);
        return;
    }
    askToStart(command);
}

void TestRunPanel::askToStart(const RunControl::Command& command)
{
    // Its allowed speeds depend on the variant: a drive that does not report it is asked once.
    if (!VariantQuestion::ensure(this, m_drives, m_slave, VariantNeed::Purpose::Start)) {
        setMessage(
            tr("Not started: the variant of %1 was not given.").arg(m_drives->label(m_slave)),
            true);
        return;
    }
    // What will run, and which other drives the start reaches, read from the drives now.
    m_busy = true;
    updateEnabled();
    setMessage(tr("Reading what the start will run…"), false);
    const int slave = m_slave;
    QPointer<TestRunPanel> self(this);
    m_preview->read(slave, m_commandedCcw, [self, command, slave](const StartPreview::Result& r) {
        if (!self)
            return;
        self->m_busy = false;
        self->updateEnabled();
        self->setMessage(QString(), false);
        // Asked once per drive, and every time the start also reaches other drives.
        if (s_confirmed.contains(slave) && r.alsoReaches.isEmpty()) {
            self->send(command);
            return;
        }
        const QString text = r.question(self->m_isDc ? command.speed : QString());
        self->m_lastQuestion = text;
        ConfirmBox::ask(self, tr("Start the motor"), text, tr("Start the motor"),
                        [self, command, slave] {
                            if (!self)
                                return;
                            s_confirmed.insert(slave);
                            self->send(command);
                        });
    });
}

void TestRunPanel::send(const RunControl::Command& command)
{
    m_busy = true;
    updateEnabled();
    setMessage(tr("Sending %1…").arg(RunControl::actionName(command.action)), false);
    QPointer<TestRunPanel> self(this);
    m_control.execute(m_session, command, [self, command](const RunControl::Outcome& o) {
        if (!self)
            return;
        self->showOutcome(o);
        if (o.sent &&
            (command.action == RunControl::Action::Cw || command.action == RunControl::Action::Ccw))
            self->m_commandedCcw = command.action == RunControl::Action::Ccw;
        if (o.sent && command.action == RunControl::Action::Select)
            self->m_commandedCcw.reset(); // the selected SPno's own direction counts again
        if (o.failure == RunControl::Failure::Priority)
            self->refresh(); // the drive was switched to I/O priority meanwhile
        if (!o.sent) {
            self->finishCommand(false);
            return;
        }
        // The drives of its communication group executed a motion command too, or ignored
        // it: what each does is read from it, as is the drive's own state.
        const bool motion = o.plan.meta && o.plan.meta->safety == QLatin1String("motion");
        self->m_state->readAfter(
            &self->m_control, self->m_session,
            motion ? self->m_session->reachedDrives() : QVector<DeviceSession*>(), kSettleMs,
            [self, ok = o.ok, start = command.action == RunControl::Action::Start](bool allRun) {
                if (!self)
                    return;
                // A start that left a child standing is said where the user looks first.
                if (!allRun && start)
                    self->setMessage(self->m_message->text() + QLatin1Char('\n') +
                                         tr("Not every drive of its communication group runs: "
                                            "see below."),
                                     true);
                self->finishCommand(ok);
            });
    });
}

void TestRunPanel::finishCommand(bool ok)
{
    m_busy = false;
    updateEnabled();
    emit commandFinished(ok);
}

void TestRunPanel::showOutcome(const RunControl::Outcome& o)
{
    if (o.ok) {
        setMessage(tr("Sent: %1").arg(o.plan.description), false);
        return;
    }
    QString text = o.error; // with the drive's error code, when it gave one
    if (!o.explanation.isEmpty())
        text += QStringLiteral("\n") + o.explanation;
    setMessage(text, true);
}

QString TestRunPanel::priorityExplanation() const
{
    return m_priorityBox && !m_priorityBox->isHidden() ? m_priorityBox->explanation() : QString();
}

QString TestRunPanel::stateText() const
{
    return m_state ? m_state->text() : QString();
}
QString TestRunPanel::messageText() const
{
    return m_message->text();
}
QString TestRunPanel::speedError() const
{
    return m_dc ? m_dc->speedError() : QString();
}
QString TestRunPanel::pollingWarning() const
{
    return m_warning && !m_warning->isHidden() ? m_warning->text() : QString();
}

void TestRunPanel::setMonitorHub(MonitorHub* hub)
{
    if (!m_session || m_live || !hub)
        return;
    m_live = new RunLiveState(hub, m_slave, this);
    m_side->insertWidget(1, m_live); // under why the drive refuses commands, if it does
}

void TestRunPanel::setPollingActive(bool active)
{
    m_pollingActive = active;
    updateWarning();
}

void TestRunPanel::updateEnabled()
{
    if (!m_commands)
        return;
    m_commands->setEnabled(m_enabled);
    if (m_dbu) {
        m_dbu->setIoReturnVisible(m_enabled); // only a drive in communication priority goes back
        m_dbu->setBusy(m_busy);
    }
    if (m_dc)
        m_dc->setBusy(m_busy);
    const bool explain = !m_enabled && !m_currentPriority.isEmpty() &&
                         RoleEvaluator::parameter(m_session->profile(), kPriority);
    if (explain)
        m_priorityBox->setCurrent(m_currentPriority);
    m_priorityBox->setVisible(explain);
}

void TestRunPanel::updateWarning()
{
    if (!m_warning)
        return;
    const bool show = !m_pollingActive && m_commLossSeconds > 0;
    m_warning->setText(
        show ? tr("Polling is paused: the controller brakes the motor %1 s after the last frame "
                  "it receives (%2). Resume polling to keep the motor running.")
                   .arg(ValueCodec::formatNumber(m_commLossSeconds, 1),
                        m_session->profile().parameter(kCommLoss)->label)
             : QString());
    m_warning->setVisible(show);
}

void TestRunPanel::setMessage(const QString& text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c00000;") : QString());
}

} // namespace opentop
