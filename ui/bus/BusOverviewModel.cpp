#include "bus/BusOverviewModel.h"

#include "bus/BusDrives.h"
#include "monitor/MonitorHub.h"
#include "profile/RoleEvaluator.h"
#include "session/DeviceSession.h"
#include "widgets/StaleLook.h"

#include <QBrush>
#include <QColor>

namespace opentop {

BusOverviewModel::BusOverviewModel(BusDrives* drives, MonitorHub* hub, QObject* parent)
    : QAbstractTableModel(parent)
    , m_drives(drives)
    , m_hub(hub)
{
    connect(drives, &BusDrives::driveAdded, this, &BusOverviewModel::rebuild);
    connect(drives, &BusDrives::driveRemoved, this, &BusOverviewModel::rebuild);
    connect(drives, &BusDrives::driveChanged, this, &BusOverviewModel::rebuild);
    // Sixteen drives at 10 Hz are 160 samples a second; the grid is repainted five times a
    // second instead, which people cannot tell apart and costs a fraction.
    m_refresh.setInterval(200);
    m_refresh.setSingleShot(true);
    connect(&m_refresh, &QTimer::timeout, this, [this] {
        if (!m_slaves.isEmpty())
            emit dataChanged(index(0, 0), index(m_slaves.size() - 1, ColumnCount - 1));
    });
    connect(hub, &MonitorHub::sample, this, [this](int slave, const MonitorSample&) {
        m_errors.remove(slave);
        if (!m_refresh.isActive())
            m_refresh.start();
    });
    connect(hub, &MonitorHub::error, this, [this](int slave, const QString& text) {
        m_errors.insert(slave, text);
        if (!m_refresh.isActive())
            m_refresh.start();
    });
    // A drive that stops answering, or a lost link, greys its row within a tick.
    m_age.setInterval(250);
    connect(&m_age, &QTimer::timeout, &m_refresh, [this] {
        if (!m_refresh.isActive())
            m_refresh.start(0);
    });
    m_age.start();
    connect(hub, &MonitorHub::linkChanged, this, [this] { m_refresh.start(0); });
    rebuild();
}

bool BusOverviewModel::isStale(int slave) const
{
    return m_hub->freshness(slave, QDateTime::currentDateTimeUtc()) != Freshness::State::Live;
}

void BusOverviewModel::rebuild()
{
    QVector<int> slaves;
    for (int s : m_drives->slaves()) {
        if (m_drives->session(s))
            slaves << s;
    }
    if (slaves == m_slaves) {
        if (!m_slaves.isEmpty())
            emit dataChanged(index(0, 0), index(m_slaves.size() - 1, ColumnCount - 1));
        return;
    }
    beginResetModel();
    m_slaves = slaves;
    endResetModel();
}

int BusOverviewModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_slaves.size();
}

int BusOverviewModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant BusOverviewModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Drive:
        return tr("Drive");
    case State:
        return tr("State");
    case Speed:
        return tr("Speed");
    case DisplaySpeed:
        return tr("Display");
    case Target:
        return tr("Target");
    case Load:
        return tr("Load");
    case Alarm:
        return tr("Alarm");
    case Communication:
        return tr("Last answer");
    default:
        return {};
    }
}

QString BusOverviewModel::text(int slave, Column column) const
{
    return cell(slave, column);
}

QString BusOverviewModel::cell(int slave, int column) const
{
    const DeviceInfo info = m_drives->info(slave);
    if (column == Drive)
        return tr("%1 %2").arg(slave).arg(info.shortModel());
    const std::optional<MonitorSample> s = m_hub->latest(slave);
    if (column == Communication) {
        const QDateTime now = QDateTime::currentDateTimeUtc();
        const QString age =
            StaleLook::ageText(m_hub->freshness(slave, now), m_hub->lastAnswer(slave), now);
        if (!m_drives->linkUp())
            return tr("connection lost; %1").arg(age);
        if (m_errors.contains(slave))
            return tr("no answer: %1; %2").arg(m_errors.value(slave), age);
        return age;
    }
    if (!s)
        return QString();
    const DeviceSession* session = m_drives->session(slave);
    if (!session)
        return QString();
    const Profile& profile = session->profile();
    // Speeds signed by the direction, as the drive's own display shows them.
    const auto roleText = [&](const QString& role) {
        const ParameterMeta* m = RoleEvaluator::parameter(profile, role);
        return m ? s->signedText(m->name) : QString();
    };
    switch (column) {
    case State:
        return s->stateText();
    case Speed:
        return roleText(QStringLiteral("currentSpeed"));
    case DisplaySpeed:
        return s->currentShown
                   ? QStringLiteral("%1 %2").arg(s->currentShown->text, s->currentShown->unit)
                   : QString();
    case Target:
        return roleText(QStringLiteral("targetSpeed"));
    case Load:
        return roleText(QStringLiteral("load"));
    case Alarm:
        if (!s->alarmActive)
            return QString();
        if (!*s->alarmActive)
            return tr("none");
        return s->activeAlarm
                   ? QStringLiteral("%1 %2").arg(s->activeAlarm->panel, s->activeAlarm->name)
                   : tr("active");
    default:
        return QString();
    }
}

QVariant BusOverviewModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= m_slaves.size())
        return {};
    const int slave = m_slaves[index.row()];
    if (role == Qt::DisplayRole || role == Qt::ToolTipRole)
        return cell(slave, index.column());
    if (role == Qt::TextAlignmentRole && index.column() >= Speed && index.column() <= Load)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    const std::optional<MonitorSample> s = m_hub->latest(slave);
    const bool stale = isStale(slave);
    if (role == StaleRole)
        return stale;
    // Not live: every value grey, an alarm no longer red (it may have cleared meanwhile).
    if (role == Qt::ForegroundRole && stale && index.column() != Drive)
        return QBrush(StaleLook::grey());
    if (role == Qt::BackgroundRole) {
        if (stale)
            return index.column() == Communication ? QVariant(QBrush(QColor(0xff, 0xe0, 0x82)))
                                                   : QVariant();
        if (index.column() == Alarm && s && s->alarmActive.value_or(false))
            return QBrush(QColor(0xe5, 0x1c, 0x23));
        if (index.column() == Communication && m_errors.contains(slave))
            return QBrush(QColor(0xff, 0xe0, 0x82));
    }
    if (role == Qt::ForegroundRole && index.column() == Alarm && s &&
        s->alarmActive.value_or(false))
        return QBrush(Qt::white);
    return {};
}

} // namespace opentop
