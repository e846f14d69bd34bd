#include "run/TestRunPanel.h"

#include "bus/BusDrives.h"
#include "profile/ProfileRegistry.h"
#include "profile/RoleEvaluator.h"
#include "profile/ValueCodec.h"
#include "run/MotionPriorityBox.h"
#include "session/DeviceSession.h"
#include "widgets/ConfirmBox.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

namespace {

const QString kPriority = QStringLiteral("motionPriority");
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
    layout->addWidget(new QLabel(tr("<b>Test run of machine number %1</b>").arg(slave), this));
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
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
    m_isDc =
        RoleEvaluator::parameter(profile, kSpeedCommand) && !profile.role(QStringLiteral("start"));

    m_priorityBox = new MotionPriorityBox(m_session, this);
    m_priorityBox->hide();
    connect(m_priorityBox, &MotionPriorityBox::switching, this,
            [this] { setMessage(tr("Switching to communication priority…"), false); });
    connect(m_priorityBox, &MotionPriorityBox::switched, this,
            [this](bool ok, const QString& message) {
                setMessage(message, !ok);
                refresh();
            });
    layout->addWidget(m_priorityBox);

    m_commands = new QWidget(this);
    layout->addWidget(m_commands);
    if (m_isDc)
        buildDc();
    else
        buildDbu();
    m_warning = new QLabel(this);
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(QStringLiteral("color: #a05000;"));
    m_warning->hide();
    layout->addWidget(m_warning);
    layout->addWidget(m_message);
    m_state = new QLabel(this);
    m_state->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_state);
    layout->addStretch();
    updateEnabled();
    refresh();
}

QPushButton* TestRunPanel::addButton(const QString& text, const QString& name,
                                     const std::function<void()>& onClick)
{
    auto* button = new QPushButton(text, m_commands);
    button->setObjectName(name);
    connect(button, &QPushButton::clicked, this, onClick);
    return button;
}

void TestRunPanel::buildDbu()
{
    using A = RunControl::Action;
    auto* grid = new QGridLayout(m_commands);
    const Profile& profile = m_session->profile();
    const QPair<A, QString> items[] = {{A::Start, tr("&Start")}, {A::Stop, tr("S&top")},
                                       {A::Cw, tr("&CW")},       {A::Ccw, tr("CC&W")},
                                       {A::Hold, tr("&Hold")},   {A::Free, tr("&Free")}};
    for (int i = 0; i < 6; ++i) {
        RunControl::Command c;
        c.action = items[i].first;
        if (!RoleEvaluator::parameter(profile, RunControl::roleOf(c.action)))
            continue;
        const bool starts = c.action == A::Start;
        QPushButton* b = addButton(items[i].second, RunControl::actionName(c.action),
                                   [this, c, starts] { run(c, starts); });
        if (c.action != A::Stop)
            m_whileIdle << b;
        grid->addWidget(b, i / 2, i % 2);
    }
    const ParameterMeta* select = RoleEvaluator::parameter(profile, QStringLiteral("select"));
    if (!select)
        return;
    m_spno = new QComboBox(m_commands);
    m_spno->setObjectName(QStringLiteral("spno"));
    for (const EnumOption& o : select->specFor(m_session->context()).options)
        m_spno->addItem(o.label, int(o.value + 1)); // running data N is code N-1
    grid->addWidget(m_spno, 3, 0);
    m_whileIdle << m_spno;
    grid->addWidget(addButton(tr("Se&lect running data"), QStringLiteral("select"),
                              [this] {
                                  RunControl::Command c;
                                  c.action = RunControl::Action::Select;
                                  c.select = m_spno->currentData().toInt();
                                  run(c, false);
                              }),
                    3, 1);
    m_whileIdle << grid->itemAtPosition(3, 1)->widget();
}

void TestRunPanel::buildDc()
{
    auto* grid = new QGridLayout(m_commands);
    m_speed = new QLineEdit(m_commands);
    m_speed->setObjectName(QStringLiteral("speed"));
    m_speed->setPlaceholderText(tr("set point, e.g. 50 or -20"));
    m_speedUnit = new QLabel(m_commands);
    m_speedError = new QLabel(m_commands);
    m_speedError->setObjectName(QStringLiteral("speedError"));
    m_speedError->setWordWrap(true);
    m_speedError->setStyleSheet(QStringLiteral("color: #c00000;"));
    connect(m_speed, &QLineEdit::textChanged, this, &TestRunPanel::updateSpeed);
    m_setSpeed = addButton(tr("Set s&peed"), QStringLiteral("setSpeed"), [this] {
        const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), kSpeedCommand);
        const ValueCodec::Encoded e =
            ValueCodec::encodeText(*meta, m_speed->text().trimmed(), m_session->context());
        RunControl::Command c;
        c.action = RunControl::Action::Speed;
        c.speed = m_speed->text().trimmed();
        run(c, e.ok && e.raw != 0);
    });
    connect(m_speed, &QLineEdit::returnPressed, m_setSpeed, &QPushButton::click);
    m_whileIdle << m_speed;
    grid->addWidget(new QLabel(tr("Speed command:"), m_commands), 0, 0);
    grid->addWidget(m_speed, 0, 1);
    grid->addWidget(m_speedUnit, 0, 2);
    grid->addWidget(m_setSpeed, 0, 3);
    grid->addWidget(m_speedError, 1, 0, 1, 4);
    auto simple = [this](RunControl::Action action) {
        RunControl::Command c;
        c.action = action;
        return [this, c] { run(c, false); };
    };
    grid->addWidget(addButton(tr("&Brake (speed 0)"), QStringLiteral("brake"),
                              simple(RunControl::Action::Stop)),
                    2, 0, 1, 2);
    if (RoleEvaluator::parameter(m_session->profile(), QStringLiteral("coast")))
        grid->addWidget(addButton(tr("&Natural stop"), QStringLiteral("coast"),
                                  simple(RunControl::Action::Coast)),
                        2, 2, 1, 2);
    updateSpeed();
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
    if (!starts || s_confirmed.contains(m_slave)) {
        send(command);
        return;
    }
    const int slave = m_slave;
    ConfirmBox::ask(
        this, tr("Start the motor"),
        tr("This starts the motor of machine number %1. Make sure that nobody is near the "
           "machine and that it may move. STOP ALL stops every drive at any time.\n\nYou are "
           "asked once per drive while the program runs.")
            .arg(slave),
        tr("Start the motor"), [this, command, slave] {
            s_confirmed.insert(slave);
            send(command);
        });
}

void TestRunPanel::send(const RunControl::Command& command)
{
    m_busy = true;
    updateEnabled();
    setMessage(tr("Sending %1…").arg(RunControl::actionName(command.action)), false);
    QPointer<TestRunPanel> self(this);
    m_control.execute(m_session, command, [self](const RunControl::Outcome& o) {
        if (!self)
            return;
        self->showOutcome(o);
        if (o.failure == RunControl::Failure::Priority)
            self->refresh(); // the drive was switched to I/O priority meanwhile
        if (!o.sent) {
            self->m_busy = false;
            self->updateEnabled();
            emit self->commandFinished(false);
            return;
        }
        self->m_control.readState(
            self->m_session,
            [self, ok = o.ok](const RunControl::State& state) {
                if (!self)
                    return;
                self->showState(state);
                self->m_busy = false;
                self->updateEnabled();
                emit self->commandFinished(ok);
            },
            kSettleMs);
    });
}

void TestRunPanel::showOutcome(const RunControl::Outcome& o)
{
    if (o.ok) {
        setMessage(tr("Sent: %1").arg(o.plan.description), false);
        return;
    }
    QString text = o.error;
    if (!o.deviceError.isEmpty() && !text.contains(o.deviceError))
        text += QStringLiteral(" (%1)").arg(o.deviceError);
    if (!o.explanation.isEmpty())
        text += QStringLiteral("\n") + o.explanation;
    setMessage(text, true);
}

void TestRunPanel::showState(const RunControl::State& state)
{
    QStringList lines;
    if (state.running)
        lines << (*state.running ? tr("The motor is running.") : tr("The motor is stopped."));
    for (const auto& item : state.items)
        lines << tr("%1: %2").arg(item.first, item.second);
    if (!state.error.isEmpty())
        lines << tr("(not read: %1)").arg(state.error);
    m_state->setText(lines.join(QLatin1Char('\n')));
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
    return m_speedError ? m_speedError->text() : QString();
}
QString TestRunPanel::pollingWarning() const
{
    return m_warning && !m_warning->isHidden() ? m_warning->text() : QString();
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
    for (QWidget* w : std::as_const(m_whileIdle))
        w->setEnabled(!m_busy);
    updateSpeed();
    const bool explain = !m_enabled && !m_currentPriority.isEmpty() &&
                         RoleEvaluator::parameter(m_session->profile(), kPriority);
    if (explain)
        m_priorityBox->setCurrent(m_currentPriority);
    m_priorityBox->setVisible(explain);
}

void TestRunPanel::updateSpeed()
{
    if (!m_speed)
        return;
    const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), kSpeedCommand);
    const ValueContext context = m_session->context();
    QString unresolved;
    const ValueSpec& spec = meta->specFor(context, &unresolved);
    m_speedUnit->setText(unresolved.isEmpty()
                             ? tr("%1 (%2)").arg(spec.unit, ValueCodec::allowedText(*meta, context))
                             : tr("(reading %1…)").arg(unresolved));
    const QString text = m_speed->text().trimmed();
    QString error;
    if (!text.isEmpty() && unresolved.isEmpty()) {
        const ValueCodec::Encoded e = ValueCodec::encodeText(*meta, text, context);
        if (!e.ok)
            error = e.error;
    }
    m_speedError->setText(error);
    m_setSpeed->setEnabled(!m_busy && !text.isEmpty() && unresolved.isEmpty() && error.isEmpty());
}

void TestRunPanel::updateWarning()
{
    if (!m_warning)
        return;
    const bool show = !m_pollingActive && m_commLossSeconds > 0;
    m_warning->setText(
        show ? tr("Polling is paused: the controller brakes the motor %1 s after the last frame "
                  "it receives (%2). Resume polling to keep the motor running.")
                   .arg(ValueCodec::formatNumber(m_commLossSeconds, 1), kCommLoss)
             : QString());
    m_warning->setVisible(show);
}

void TestRunPanel::setMessage(const QString& text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c00000;") : QString());
}

} // namespace opentop
