#include "ui/monitor/MonitorPage.h"

#include "model/bus/DriveStatusPoller.h"
#include "model/monitor/MonitorHub.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/SpeedDisplay.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "ui/monitor/MonitorDetails.h"
#include "ui/monitor/MonitorPollBar.h"
#include "ui/monitor/MotorSpeedBox.h"
#include "ui/monitor/PanelMirrorView.h"
#include "ui/monitor/TerminalLamps.h"
#include "ui/trends/TrendChart.h"
#include "ui/trends/TrendDefaults.h"
#include "ui/widgets/StaleLook.h"
#include "ui/widgets/StatusLight.h"

#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>
#include <QScrollArea>
#include <QSplitter>
#include <QTime>
#include <QVBoxLayout>
#include <algorithm>

namespace opentop {

namespace {

const QString kCurrent = QStringLiteral("currentSpeed");
const QString kTarget = QStringLiteral("targetSpeed");
const QString kLoad = QStringLiteral("load");

QLabel* bigLabel(QWidget* parent, qreal factor)
{
    auto* l = new QLabel(QStringLiteral("—"), parent);
    QFont f = l->font();
    f.setPointSizeF(f.pointSizeF() * factor);
    f.setBold(true);
    l->setFont(f);
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return l;
}

} // namespace

MonitorPage::MonitorPage(MonitorHub* hub, DeviceParameters* parameters, QWidget* parent)
    : QWidget(parent)
    , m_hub(hub)
    , m_parameters(parameters)
    , m_slave(parameters->session()->slave())
    , m_bar(new MonitorPollBar(hub, m_slave, this))
    , m_current(bigLabel(this, 2.2))
    , m_currentDisplay(bigLabel(this, 1.3))
    , m_target(bigLabel(this, 1.3))
    , m_load(bigLabel(this, 1.3))
    , m_state(bigLabel(this, 1.3))
    , m_alarm(new QLabel(this))
    , m_chart(new TrendChart(hub, this))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_bar);
    // Paused values are no longer live.
    connect(hub, &MonitorHub::pausedChanged, this, [this] {
        if (m_look)
            m_look->update();
    });

    auto* splitter = new QSplitter(Qt::Vertical, this);
    // The values scroll when the chart below is given the height (a laptop's screen): they are
    // never squeezed on top of each other.
    auto* values = new QScrollArea(splitter);
    values->setObjectName(QStringLiteral("monitorValues"));
    values->setWidgetResizable(true);
    values->setFrameShape(QFrame::NoFrame);
    auto* top = new QWidget(values);
    auto* row = new QHBoxLayout(top);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(buildReadouts(), 3);
    row->addWidget(buildSide(), 2);
    values->setWidget(top);
    splitter->addWidget(values);
    splitter->setChildrenCollapsible(false);
    splitter->addWidget(m_chart);
    splitter->setStretchFactor(1, 1);
    m_splitter = splitter; // divided when shown and when its height changes, until dragged
    splitter->installEventFilter(this);
    connect(splitter, &QSplitter::splitterMoved, this, [this] { m_userDivided = true; });
    layout->addWidget(splitter, 1);

    m_chart->setSources(TrendDefaults::forDrive(parameters->profile(), m_slave));
    // While the drive's pages are open its trend goes on, also behind another page (once a
    // second then): coming back shows what happened meanwhile, not a gap.
    hub->record(m_slave, this);

    connect(hub, &MonitorHub::sample, this, [this](int slave, const MonitorSample& s) {
        if (slave == m_slave)
            showSample(s);
    });
    connect(hub, &MonitorHub::error, this, [this](int slave, const QString& text) {
        if (slave == m_slave)
            showError(text);
    });
    // Written speed display settings change what the display shows: read them again, once.
    m_displayChanged.setSingleShot(true);
    m_displayChanged.setInterval(300);
    // The hub as context: a page waiting for its deletion must not reach a hub already gone.
    connect(&m_displayChanged, &QTimer::timeout, hub,
            [hub, slave = m_slave] { hub->refreshDisplay(slave); });
    const QStringList displayNames = SpeedDisplay::Names::withPrefix().all();
    connect(parameters, &DeviceParameters::entryChanged, this,
            [this, displayNames](const QString& n) {
                const DeviceParameters::Entry* e = m_parameters->entry(n);
                if (displayNames.contains(n) && e && e->state == DeviceParameters::State::Clean)
                    m_displayChanged.start();
                m_details->parameterChanged(n);
                if (m_last)
                    showPanel(*m_last);
            });
    // One rule for every live value (monitor/Freshness): its age shown, grey once not live.
    // A page removed from the tabs is deleted later, possibly after the hub (a reconnection).
    const QPointer<MonitorHub> alive(hub);
    const int slave = m_slave;
    m_look = new StaleLook(
        [alive, slave](const QDateTime& now) {
            return alive ? alive->freshness(slave, now) : Freshness::State::None;
        },
        [alive, slave] { return alive ? alive->lastAnswer(slave) : QDateTime(); }, this);
    for (QWidget* w : {static_cast<QWidget*>(m_current), static_cast<QWidget*>(m_currentDisplay),
                       static_cast<QWidget*>(m_target), static_cast<QWidget*>(m_load),
                       static_cast<QWidget*>(m_state)})
        m_look->addWidget(w);
    if (m_motorSpeed)
        m_look->addWidget(m_motorSpeed);
    connect(m_look, &StaleLook::evaluated, this, [this, alive] {
        if (alive)
            showFreshness();
    });
    connect(hub, &MonitorHub::linkChanged, m_look, &StaleLook::update);
    connect(hub, &MonitorHub::heldChanged, m_look, &StaleLook::update);
    if (const auto latest = hub->latest(m_slave))
        showSample(*latest);
    m_look->update();
}

// Polls at the chosen rate while shown; behind another page only the recording's once a second.
void MonitorPage::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    m_hub->watch(m_slave, this);
    divide();
}

bool MonitorPage::eventFilter(QObject* watched, QEvent* event)
{
    // A dock opened below, a status line more above: divided again for the new height.
    if (watched == m_splitter && event->type() == QEvent::Resize)
        QTimer::singleShot(0, this, &MonitorPage::divide);
    return QWidget::eventFilter(watched, event);
}

void MonitorPage::divide()
{
    // Once the values are all there (built at the first sample) and the page has its height:
    // the values first, whole if they fit in three fifths (the lamps in sight on a laptop's
    // screen) and leave the chart 200 px or half, the chart the rest.
    if (m_userDivided || !m_details->isBuilt() || !isVisible() || m_splitter->height() < 200)
        return;
    const int height = m_splitter->height();
    const auto* values = static_cast<QScrollArea*>(m_splitter->widget(0));
    const int wanted = values->widget()->sizeHint().height() + 4;
    // The chart keeps 200 px where the page has them (shorter, its axes lose their titles);
    // on a short page the two share it half and half.
    const int top = std::min({wanted, height * 3 / 5, std::max(height / 2, height - 200)});
    m_splitter->setSizes({top, height - top});
}

void MonitorPage::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    m_hub->unwatch(m_slave, this);
}

QWidget* MonitorPage::buildReadouts()
{
    auto* box = new QGroupBox(tr("Live values"), this);
    auto* column = new QVBoxLayout(box);
    auto* big = new QGridLayout;
    const Profile& profile = m_parameters->profile();
    const auto caption = [this, &profile](const QString& role, const QString& fallback) {
        const ParameterMeta* m = RoleEvaluator::parameter(profile, role);
        return new QLabel(m ? m->label : fallback, this);
    };
    big->addWidget(caption(kCurrent, tr("Speed")), 0, 0);
    big->addWidget(m_current, 1, 0);
    // "32.0 m/min on the drive's display" in large type wraps under the speed rather than
    // pushing the drive's panel off the right edge of a laptop's window.
    m_currentDisplay->setWordWrap(true);
    big->addWidget(m_currentDisplay, 2, 0, 1, 4);
    // A family without a target speed or a load role shows neither caption nor value.
    for (const auto& [role, label, at] :
         {std::tuple(kTarget, m_target, 1), std::tuple(kLoad, m_load, 2)}) {
        if (!RoleEvaluator::parameter(profile, role)) {
            label->hide();
            continue;
        }
        big->addWidget(caption(role, QString()), 0, at);
        big->addWidget(label, 1, at);
    }
    big->addWidget(new QLabel(tr("State"), this), 0, 3);
    big->addWidget(m_state, 1, 3);
    column->addLayout(big);
    m_alarm->setWordWrap(true);
    m_alarm->setVisible(false);
    m_alarm->setStyleSheet(QStringLiteral("QLabel { background: #e51c23; color: white; "
                                          "padding: 4px; border-radius: 4px; }"));
    column->addWidget(m_alarm);
    m_details = new MonitorDetails(m_parameters, box);
    column->addWidget(m_details);
    column->addStretch(1);
    return box;
}

QWidget* MonitorPage::buildSide()
{
    auto* side = new QWidget(this);
    auto* column = new QVBoxLayout(side);
    column->setContentsMargins(0, 0, 0, 0);
    const Profile& profile = m_parameters->profile();
    if (PanelMirror::supported(profile)) {
        m_panel = new PanelMirrorView(side);
        column->addWidget(m_panel);
    }
    // A speed measured as a frequency (the DC controller's) needs the motor's commutations.
    const ParameterMeta* speed = RoleEvaluator::parameter(profile, kCurrent);
    if (MotorSpeedBox::appliesTo(speed)) {
        m_motorSpeed = new MotorSpeedBox(*speed, m_slave, side);
        column->addWidget(m_motorSpeed);
    }
    column->addStretch(1);
    return side;
}

void MonitorPage::setCommutationsPerRevolution(double count)
{
    if (m_motorSpeed)
        m_motorSpeed->setCommutationsPerRevolution(count);
}

void MonitorPage::showSample(const MonitorSample& s)
{
    const Profile& profile = m_parameters->profile();
    if (!m_details->isBuilt()) {
        // The speeds and the load are shown large above; not twice.
        QStringList large;
        for (const QString& role : {kCurrent, kTarget, kLoad}) {
            if (const ParameterMeta* m = RoleEvaluator::parameter(profile, role))
                large << m->name;
        }
        m_details->build(s, large);
        QTimer::singleShot(0, this, &MonitorPage::divide); // once the new rows are laid out
    }
    m_last = s;
    ++m_samples;
    m_details->showSample(s);
    // Speeds signed by the direction: a register holding the magnitude would hide a reverse run.
    const auto text = [&](const QString& role) {
        const ParameterMeta* m = RoleEvaluator::parameter(profile, role);
        const QString t = m ? s.signedText(m->name) : QString();
        return t.isEmpty() ? QStringLiteral("—") : t;
    };
    m_current->setText(text(kCurrent));
    m_currentDisplay->setText(
        s.currentShown && s.currentShown->unit != QLatin1String("r/min")
            ? tr("%1 %2 on the drive's display").arg(s.currentShown->text, s.currentShown->unit)
            : QString());
    m_currentDisplay->setVisible(!m_currentDisplay->text().isEmpty());
    m_target->setText(text(kTarget));
    m_load->setText(text(kLoad));
    m_state->setText(s.running ? s.stateText() : QStringLiteral("—"));
    const bool alarm = s.alarmActive.value_or(false);
    m_alarm->setVisible(alarm);
    if (alarm) {
        m_alarm->setText(s.activeAlarm ? tr("Alarm %1 %2 — %3")
                                             .arg(s.activeAlarm->panel, s.activeAlarm->name,
                                                  s.activeAlarm->remedy)
                                       : tr("Alarm active (reading which one…)"));
    }
    m_lastError.clear();
    if (m_look)
        m_look->update(); // live again before the panel's light is set
    showPanel(s);
    if (m_motorSpeed)
        m_motorSpeed->showSample(s);
}

void MonitorPage::showPanel(const MonitorSample& s)
{
    if (!m_panel)
        return;
    const Profile& profile = m_parameters->profile();
    std::optional<PanelMirror::Content> content;
    if (const ParameterMeta* m =
            RoleEvaluator::parameter(profile, QStringLiteral("panelDisplay"))) {
        const DeviceParameters::Entry* e = m_parameters->entry(m->name);
        if (e && e->device.valid)
            content = PanelMirror::Content(int(e->device.raw));
    }
    PanelMirror::Countdown countdown;
    const ProfileRole* role = profile.role(QStringLiteral("countdown"));
    int* parts[] = {&countdown.days, &countdown.hours, &countdown.minutes, &countdown.seconds};
    for (int i = 0; role && i < 4 && i < role->parameters.size(); ++i) {
        const DeviceParameters::Entry* e = m_parameters->entry(role->parameters[i]);
        *parts[i] = e && e->device.valid ? int(e->device.number) : 0;
    }
    m_panel->setShown(PanelMirror::show(profile, s, content, countdown),
                      content ? PanelMirror::contentName(*content) : QString());
    DriveStatus status;
    status.polled = status.answered = true;
    status.running = s.running;
    status.reverse = s.reverse;
    status.alarmActive = s.alarmActive;
    status.alarmCode = s.activeAlarmCode;
    status.alarm = s.activeAlarm;
    DriveStatusPoller::applyLed(&status, &profile);
    if (!m_look || m_look->state() == Freshness::State::Live)
        m_panel->light()->setStatus(status);
}

void MonitorPage::showError(const QString& text)
{
    m_lastError = text;
    m_look->update();
}

void MonitorPage::showFreshness()
{
    m_bar->showFreshness(*m_look, m_lastError);
    const bool stale = m_look->state() == Freshness::State::Stale;
    m_details->setStale(stale);
    if (m_panel)
        m_panel->setStale(stale, tr("No live state: %1").arg(m_look->ageText()));
    const QString alarmStyle =
        QStringLiteral("QLabel { background: %1; color: white; "
                       "padding: 4px; border-radius: 4px; }")
            .arg(stale ? StaleLook::grey().name() : QStringLiteral("#e51c23"));
    if (m_alarm->styleSheet() != alarmStyle)
        m_alarm->setStyleSheet(alarmStyle);
    m_alarm->setProperty(StaleLook::kProperty, stale);
}

QString MonitorPage::pollText() const
{
    return m_bar->text();
}

QString MonitorPage::valueText(const QString& parameter) const
{
    const Profile& profile = m_parameters->profile();
    for (const auto& [role, label] :
         {std::pair(kCurrent, m_current), std::pair(kTarget, m_target), std::pair(kLoad, m_load)}) {
        const ParameterMeta* m = RoleEvaluator::parameter(profile, role);
        if (m && m->name == parameter)
            return label->text();
    }
    const QLabel* l = m_details->value(parameter);
    return l ? l->text() : QString();
}

QString MonitorPage::currentSpeedText() const
{
    return m_motorSpeed ? m_current->text() + QStringLiteral(" · ") + m_motorSpeed->speedText()
                        : m_current->text();
}

TerminalLamps* MonitorPage::lamps(const QString& parameter) const
{
    return m_details->lamps(parameter);
}

QString MonitorPage::displaySpeedText() const
{
    return m_currentDisplay->text();
}

QString MonitorPage::alarmText() const
{
    return m_alarm->isHidden() ? QString() : m_alarm->text();
}

QString MonitorPage::statusText() const
{
    return m_state->text();
}

} // namespace opentop
