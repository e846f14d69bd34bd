#include "ui/bus/BusOverviewModel.h"

#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "model/profile/RoleEvaluator.h"
#include "model/session/DeviceSession.h"
#include "ui/widgets/PlainText.h"
#include "ui/widgets/StaleLook.h"

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
    // Sixteen drives at 10 Hz are 160 samples a second; the grid follows five times a second
    // instead, which people cannot tell apart and costs a fraction. The same tick moves the
    // ages on and greys a drive that stops answering.
    m_refresh.setInterval(200);
    connect(&m_refresh, &QTimer::timeout, this, &BusOverviewModel::refresh);
    connect(hub, &MonitorHub::sample, this, [this](int slave, const MonitorSample&) {
        m_errors.remove(slave);
        markDue(slave);
    });
    connect(hub, &MonitorHub::error, this, [this](int slave, const QString& text) {
        m_errors.insert(slave, text);
        markDue(slave);
    });
    // A lost link greys every row at once.
    connect(hub, &MonitorHub::linkChanged, this, &BusOverviewModel::refresh);
    rebuild();
}

bool BusOverviewModel::isStale(int slave) const
{
    return m_hub->freshness(slave, QDateTime::currentDateTimeUtc()) != Freshness::State::Live;
}

void BusOverviewModel::markDue(int slave)
{
    const int row = rowOf(slave);
    if (row >= 0)
        m_rows[row].valuesDue = true;
}

void BusOverviewModel::rebuild()
{
    QVector<int> slaves;
    for (int s : m_drives->slaves()) {
        if (m_drives->session(s))
            slaves << s;
    }
    if (slaves != m_slaves) {
        beginResetModel();
        m_slaves = slaves;
        m_rows = QVector<Row>(slaves.size());
        const QDateTime now = QDateTime::currentDateTimeUtc();
        for (int r = 0; r < m_slaves.size(); ++r)
            evaluate(r, now);
        endResetModel();
    } else {
        for (Row& row : m_rows)
            row.valuesDue = true; // identified again: another model, other values
        refresh();
    }
    if (m_slaves.isEmpty())
        m_refresh.stop();
    else if (!m_refresh.isActive())
        m_refresh.start();
}

void BusOverviewModel::refresh()
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    for (int r = 0; r < m_slaves.size(); ++r) {
        // One cell at a time: a view repaints that cell only, not the whole grid.
        for (int c : evaluate(r, now))
            emit dataChanged(index(r, c), index(r, c));
    }
}

QVector<int> BusOverviewModel::evaluate(int r, const QDateTime& now)
{
    const int slave = m_slaves[r];
    const Freshness::State state = m_hub->freshness(slave, now);
    Row next = m_rows[r];
    next.stale = state != Freshness::State::Live;
    next.error = m_errors.contains(slave);
    if (next.valuesDue) {
        next.valuesDue = false;
        const std::optional<MonitorSample> s = m_hub->latest(slave);
        next.alarm = s && s->alarmActive.value_or(false);
        for (int c = 0; c < ColumnCount; ++c) {
            if (c != Communication)
                next.text[c] = valueCell(slave, c, s);
        }
    }
    next.text[Communication] = communicationCell(slave, state, now);
    const Row& was = m_rows[r];
    const bool look = next.stale != was.stale || next.alarm != was.alarm || next.error != was.error;
    QVector<int> changed;
    for (int c = 0; c < ColumnCount; ++c) {
        if (look || next.text[c] != was.text[c])
            changed << c;
    }
    m_rows[r] = std::move(next);
    return changed;
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
    const int row = rowOf(slave);
    return row >= 0 ? m_rows[row].text[column] : QString();
}

QString BusOverviewModel::communicationCell(int slave, Freshness::State state,
                                            const QDateTime& now) const
{
    const QString age = StaleLook::ageText(state, m_hub->lastAnswer(slave), now);
    if (!m_drives->linkUp())
        return tr("connection lost; %1").arg(age);
    if (m_errors.contains(slave))
        return tr("no answer: %1; %2").arg(m_errors.value(slave), age);
    return age;
}

QString BusOverviewModel::valueCell(int slave, int column,
                                    const std::optional<MonitorSample>& s) const
{
    if (column == Drive)
        return tr("%1 %2").arg(slave).arg(m_drives->info(slave).shortModel());
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
    const Row& row = m_rows[index.row()];
    const int column = index.column();
    if (role == Qt::DisplayRole)
        return row.text[column];
    if (role == Qt::ToolTipRole) // a name or model as the drive has it
        return PlainText::asWritten(row.text[column]);
    if (role == Qt::TextAlignmentRole && column >= Speed && column <= Load)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == StaleRole)
        return row.stale;
    // Not live: every value grey, an alarm no longer red (it may have cleared meanwhile).
    if (role == Qt::ForegroundRole && row.stale && column != Drive)
        return QBrush(StaleLook::grey());
    if (role == Qt::BackgroundRole) {
        if (row.stale)
            return column == Communication ? QVariant(QBrush(QColor(0xff, 0xe0, 0x82)))
                                           : QVariant();
        if (column == Alarm && row.alarm)
            return QBrush(QColor(0xe5, 0x1c, 0x23));
        if (column == Communication && row.error)
            return QBrush(QColor(0xff, 0xe0, 0x82));
    }
    if (role == Qt::ForegroundRole && column == Alarm && row.alarm)
        return QBrush(Qt::white);
    return {};
}

} // namespace opentop
