#include "ui/run/RunLiveState.h"

#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/RunningData.h"
#include "model/session/DeviceSession.h"
#include "model/session/Freshness.h"
#include "transport/ModbusClient.h"

#include <QGridLayout>
#include <QLabel>

namespace opentop {

namespace {

const QString kState = QStringLiteral("state");
const QString kAlarm = QStringLiteral("alarm");
const QString kSpno = QStringLiteral("spno");
constexpr int kAgeTickMs = 250;

} // namespace

RunLiveState::RunLiveState(MonitorHub* hub, int slave, QWidget* parent)
    : QGroupBox(tr("The drive now"), parent)
    , m_hub(hub)
    , m_slave(slave)
{
    setObjectName(QStringLiteral("runLiveState"));
    auto* grid = new QGridLayout(this);
    grid->setColumnStretch(3, 1); // the age right beside its value
    const DeviceSession* session = hub->drives()->session(slave);
    if (session) {
        const Profile& profile = session->profile();
        for (const char* role : {"currentSpeed", "targetSpeed", "load", "running"}) {
            const ParameterMeta* meta = RoleEvaluator::parameter(profile, QLatin1String(role));
            // The running role of a bit field is the state row; a number (a DC controller's
            // output duty) is a value of its own.
            if (!meta || meta->type == DataType::Bits || row(meta->name))
                continue;
            addRow(meta->name, meta->label);
            if (m_speedRow.isEmpty() && QLatin1String(role) == QLatin1String("currentSpeed"))
                m_speedRow = meta->name;
            if (QLatin1String(role) == QLatin1String("running"))
                m_dutyRow = meta->name;
        }
        if (profile.role(QStringLiteral("running")))
            addRow(kState, tr("State"));
        if (profile.role(QStringLiteral("alarmActive")))
            addRow(kAlarm, tr("Alarm"));
        // The running data the drive runs, as it reports it: what the selector below offers to
        // send is the user's choice, not this.
        const ParameterMeta* selected =
            RoleEvaluator::parameter(profile, QStringLiteral("selected"));
        const ProfileRole* monitored = profile.role(QStringLiteral("monitor"));
        if (selected && monitored && monitored->parameters.contains(selected->name))
            addRow(kSpno, tr("Running data"));
    }
    for (int i = 0; i < m_rows.size(); ++i) {
        auto* label = new QLabel(m_rows[i].value->property("label").toString(), this);
        label->setBuddy(m_rows[i].value);
        grid->addWidget(label, i, 0);
        grid->addWidget(m_rows[i].value, i, 1);
        grid->addWidget(m_rows[i].age, i, 2);
    }
    connect(hub, &MonitorHub::sample, this, [this](int from, const MonitorSample& sample) {
        if (from == m_slave)
            showSample(sample);
    });
    connect(hub, &MonitorHub::error, this, [this](int from, const QString&) {
        if (from == m_slave)
            updateAges();
    });
    m_timer.setInterval(kAgeTickMs);
    connect(&m_timer, &QTimer::timeout, this, &RunLiveState::updateAges);
    if (const std::optional<MonitorSample> latest = hub->latest(slave))
        showSample(*latest);
    else
        updateAges();
}

RunLiveState::~RunLiveState()
{
    if (m_hub && m_watching)
        m_hub->unwatch(m_slave, this);
}

void RunLiveState::addRow(const QString& key, const QString& label)
{
    Row r;
    r.key = key;
    r.value = new QLabel(this);
    r.value->setObjectName(QStringLiteral("live_") + key);
    r.value->setProperty("label", tr("%1:").arg(label));
    r.value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    r.age = new QLabel(this);
    r.age->setObjectName(QStringLiteral("age_") + key);
    r.age->setStyleSheet(QStringLiteral("color: #808080;"));
    m_rows << r;
}

const RunLiveState::Row* RunLiveState::row(const QString& key) const
{
    for (const Row& r : m_rows) {
        if (r.key == key)
            return &r;
    }
    return nullptr;
}

QString RunLiveState::valueText(const QString& key) const
{
    const Row* r = row(key);
    return r ? r->value->text() : QString();
}

QString RunLiveState::ageText(const QString& key) const
{
    const Row* r = row(key);
    return r ? r->age->text() : QString();
}

void RunLiveState::showSample(const MonitorSample& sample)
{
    m_last = sample.timestamp;
    for (Row& r : m_rows) {
        if (r.key == kState) {
            QString text = sample.stateText();
            if (sample.running && *sample.running) {
                // A DC controller says how hard it drives: "Running (Output PWM duty 30.0 %)".
                if (const MonitorValue* v = sample.find(m_dutyRow); v && v->meta)
                    text = tr("%1 (%2 %3)").arg(text, v->meta->label, v->text);
            }
            r.value->setText(text.isEmpty() ? tr("not reported") : text);
        } else if (r.key == kSpno) {
            const DeviceSession* session = m_hub ? m_hub->drives()->session(m_slave) : nullptr;
            const std::optional<int> spno =
                session ? RunningData::selected(
                              session->profile(),
                              [&sample](const QString& name) { return sample.rawOf(name); })
                        : std::nullopt;
            r.value->setText(spno ? tr("SPno%1").arg(*spno) : tr("not read"));
        } else if (r.key == kAlarm) {
            if (!sample.alarmActive)
                r.value->setText(tr("not read"));
            else if (!*sample.alarmActive)
                r.value->setText(tr("none"));
            else if (sample.activeAlarm)
                r.value->setText(
                    tr("%1 %2").arg(sample.activeAlarm->panel, sample.activeAlarm->name));
            else
                r.value->setText(tr("active"));
        } else {
            const QString text = sample.signedText(r.key);
            r.value->setText(text.isEmpty() ? tr("not read") : text);
        }
    }
    updateAges();
}

void RunLiveState::updateAges()
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const bool linkUp = m_hub && m_hub->drives()->client() && m_hub->drives()->client()->isOpen() &&
                        m_hub->lastError(m_slave).isEmpty();
    const Freshness::State state =
        Freshness::of(m_last, now, m_hub ? m_hub->interval() : 200, linkUp);
    m_stale = state != Freshness::State::Live;
    QString age;
    if (state == Freshness::State::None)
        age = m_watching ? tr("waiting for the first answer…") : tr("not watched");
    else if (state == Freshness::State::Stale)
        age = Freshness::staleText(m_last, now);
    else
        age = Freshness::ageText(m_last, now);
    const QString style = m_stale ? QStringLiteral("color: #808080;") : QString();
    const QString tip = m_stale ? tr("Not live: %1").arg(age) : age;
    for (Row& r : m_rows) {
        if (state == Freshness::State::None)
            r.value->setText(QString());
        // Every sample comes here: a style sheet is applied (costly) only when it changes.
        if (r.value->styleSheet() != style)
            r.value->setStyleSheet(style);
        r.age->setText(age);
        if (r.value->toolTip() != tip)
            r.value->setToolTip(tip);
    }
    emit updated();
}

void RunLiveState::showEvent(QShowEvent* event)
{
    QGroupBox::showEvent(event);
    if (m_hub && !m_watching) {
        m_watching = true;
        m_hub->watch(m_slave, this);
    }
    m_timer.start();
    updateAges();
}

void RunLiveState::hideEvent(QHideEvent* event)
{
    QGroupBox::hideEvent(event);
    if (m_hub && m_watching)
        m_hub->unwatch(m_slave, this);
    m_watching = false;
    m_timer.stop();
}

} // namespace opentop
