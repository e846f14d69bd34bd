#include "ui/bus/BusListModel.h"

#include "model/profile/ProfileRegistry.h"
#include "ui/widgets/PlainText.h"
#include "ui/widgets/StaleLook.h"
#include "ui/widgets/StatusLight.h"

#include <QBrush>
#include <QColor>
#include <QGuiApplication>
#include <algorithm>

namespace opentop {

namespace {

const QColor kProblem(0xb0, 0x1c, 0x1c);
const QColor kGood(0x1b, 0x7f, 0x2a);

} // namespace

BusListModel::BusListModel(QObject* parent)
    : QAbstractTableModel(parent)
{
    // A drive that stops answering greys out by the clock, not only when a poll ends.
    m_age.setInterval(500);
    connect(&m_age, &QTimer::timeout, this, [this] {
        for (int row = 0; row < m_devices.size(); ++row)
            reportIfChanged(row);
    });
    m_age.start();
}

DriveStatus::Led BusListModel::shownLed(int slave) const
{
    return m_poller ? m_poller->shownLed(slave, QDateTime::currentDateTimeUtc())
                    : DriveStatus::Led::Grey;
}

bool BusListModel::isStale(int slave) const
{
    return !m_poller ||
           m_poller->freshness(slave, QDateTime::currentDateTimeUtc()) != Freshness::State::Live;
}

void BusListModel::setPoller(DriveStatusPoller* poller)
{
    if (m_poller)
        disconnect(m_poller, nullptr, this, nullptr);
    m_poller = poller;
    if (poller)
        connect(poller, &DriveStatusPoller::statusChanged, this, &BusListModel::statusChanged);
    m_reported.clear();
    if (!m_devices.isEmpty())
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

int BusListModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_devices.size());
}

int BusListModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant BusListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::ToolTipRole && section == Switches)
        return tr("How each drive's machine number is set on its switches:\n%1")
            .arg(DeviceInfo::switchHelp());
    if (role == Qt::ToolTipRole && section == MachineNumber)
        return tr("Machine number: the drive's address on the bus (1–247)");
    if (role == Qt::ToolTipRole && section == Light)
        return tr("The drive's MONITOR LED: red alarm, green ready, orange CW, sky blue CCW, "
                  "purple external interrupt, blue memory or communication error, grey no "
                  "answer");
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Light:
        return tr("LED");
    case MachineNumber:
        return tr("No."); // short: the list shows every column whole beside the pages
    case Switches:
        return tr("Switches"); // short: the header's tooltip says which and how
    case Family:
        return tr("Family");
    case Model:
        return tr("Model");
    case Firmware:
        return tr("Firmware");
    case State:
        return tr("State");
    case Priority:
        return tr("Control priority");
    case Name:
        return tr("Name");
    }
    return {};
}

DriveStatus BusListModel::status(int slave) const
{
    return m_poller ? m_poller->status(slave) : DriveStatus();
}

QString BusListModel::duplicateHint(int slave)
{
    return tr("Two drives may share machine number %1 (%2): check the address switches of "
              "every drive on the line, give each drive its own number and restart its power; "
              "a bad termination or a swapped A/B pair also corrupts replies.")
        .arg(slave)
        .arg(DeviceInfo::addressText(slave, QString()));
}

QVariant BusListModel::display(const DeviceInfo& d, int column) const
{
    const DriveStatus s = status(d.slave);
    switch (column) {
    case Light:
        return QVariant();
    case MachineNumber:
        return d.slave;
    case Switches:
        // The positions only: the number itself (and its hex form, in the tooltip and the page
        // header) is beside it, and the list must show every column whole on a laptop.
        return DeviceInfo::switchText(d.slave, d.family);
    case Family:
        if (d.line.isSet()) // a drive of its own format: the list says which
            return tr("%1 at %2")
                .arg(d.family.isEmpty() ? tr("—") : d.family.toUpper(), d.line.text());
        return d.family.isEmpty() ? tr("—") : d.family.toUpper();
    case Model:
        if (d.variantUnknown())
            return tr("%1 — variant unknown").arg(d.family.toUpper());
        return d.model.isEmpty() ? tr("—") : d.model;
    case Firmware:
        return d.firmware.isEmpty() ? tr("—") : tr("V%1").arg(d.firmware);
    case State:
        if (d.state == DeviceInfo::State::Present && s.polled)
            return s.communicationText();
        return DeviceInfo::stateText(d.state);
    case Priority:
        return s.priorityText.isEmpty() ? tr("—") : s.priorityText;
    case Name:
        return d.machineName;
    }
    return {};
}

QString BusListModel::toolTip(const DeviceInfo& d, int column) const
{
    const DriveStatus s = status(d.slave);
    if (d.state == DeviceInfo::State::Garbled) {
        QString tip = DeviceInfo::stateText(d.state);
        if (!d.detail.isEmpty())
            tip += QStringLiteral("\n") + d.detail;
        return tip + QStringLiteral("\n") + duplicateHint(d.slave);
    }
    switch (column) {
    case Light: {
        const QDateTime now = QDateTime::currentDateTimeUtc();
        const Freshness::State state =
            m_poller ? m_poller->freshness(d.slave, now) : Freshness::State::None;
        const DriveStatus::Led led = shownLed(d.slave);
        if (state == Freshness::State::Live || led != DriveStatus::Led::Grey) {
            QString tip = tr("Status light %1: %2 (%3)")
                              .arg(s.ledLabel(led), s.ledText(),
                                   StaleLook::ageText(state, s.lastAnswer, now));
            if (led == s.led && s.ledEntry)
                tip += QLatin1Char('\n') + tr("The drive's manual: %1").arg(s.ledManualText());
            return tip;
        }
        return tr("Status light grey: not live — %1")
            .arg(StaleLook::ageText(state, s.lastAnswer, now));
    }
    case Switches:
        return DeviceInfo::addressText(d.slave, d.family) + QLatin1Char('\n') +
               DeviceInfo::switchHelp(d.family);
    case Name:
        return d.machineName.isEmpty()
                   ? tr("No name yet: Name… in the context menu (F2) names this machine")
                   : tr("%1: the name given to this machine (F2 changes it)").arg(d.machineName);
    case Family:
        if (d.line.isSet())
            return tr("Requests to this drive go out at %1, its own line format, not the "
                      "port's: the line is switched to it and back between transactions. "
                      "Change it with Line format… in the context menu.")
                .arg(d.line.text());
        break;
    case Model:
        if (d.variantUnknown())
            return tr("The drive does not report its variant. Choose it from the context menu "
                      "(Variant) so that values are checked against the right limits.");
        break;
    case State:
        if (!s.error.isEmpty())
            return s.error;
        break;
    case Priority:
        if (s.motionPriority && !*s.motionPriority)
            return tr("The drive takes run commands from its I/O terminals; test runs over the "
                      "bus need communication priority.");
        break;
    default:
        break;
    }
    return d.detail;
}

QIcon BusListModel::ledIcon(const QColor& color) const
{
    auto it = m_icons.find(color.rgba());
    if (it == m_icons.end()) {
        // Painted at the screen's scale so that it stays round and sharp on HiDPI screens.
        const qreal dpr = qApp ? qApp->devicePixelRatio() : 1.0;
        QIcon icon;
        icon.addPixmap(StatusLight::pixmap(color, 14, dpr));
        if (dpr < 2.0)
            icon.addPixmap(StatusLight::pixmap(color, 14, 2.0));
        it = m_icons.insert(color.rgba(), icon);
    }
    return *it;
}

QVariant BusListModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= m_devices.size())
        return {};
    const DeviceInfo& d = m_devices[index.row()];
    const bool garbled = d.state == DeviceInfo::State::Garbled;
    switch (role) {
    case Qt::DisplayRole:
        return display(d, index.column());
    case Qt::ToolTipRole: // names and models as the drives have them
        return PlainText::asWritten(toolTip(d, index.column()));
    case Qt::AccessibleTextRole:
        if (index.column() == Light)
            return toolTip(d, Light);
        return display(d, index.column());
    case Qt::DecorationRole:
        if (index.column() == Light)
            return ledIcon(StatusLight::color(status(d.slave), shownLed(d.slave)));
        return {};
    case Qt::ForegroundRole:
        if (garbled)
            return QBrush(kProblem);
        if (index.column() == State) {
            if (d.state == DeviceInfo::State::Present && status(d.slave).consecutiveFailures > 0)
                return QBrush(kProblem);
            if (d.state == DeviceInfo::State::Present)
                return QBrush(isStale(d.slave) ? StaleLook::grey() : kGood);
            if (d.state == DeviceInfo::State::Absent ||
                d.state == DeviceInfo::State::IdentifyFailed)
                return QBrush(kProblem);
        }
        return {};
    case Qt::BackgroundRole:
        if (garbled)
            return QBrush(QColor(0xfd, 0xec, 0xea));
        return {};
    case Qt::TextAlignmentRole:
        if (index.column() == MachineNumber)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    case SlaveRole:
        return d.slave;
    case LedRole:
        return int(shownLed(d.slave));
    case StaleRole:
        return isStale(d.slave);
    case ProblemRole:
        return garbled;
    default:
        return {};
    }
}

void BusListModel::upsert(const DeviceInfo& info)
{
    const int existing = rowOf(info.slave);
    m_reported.insert(info.slave, lookOf(info));
    if (existing >= 0) {
        m_devices[existing] = info;
        emit dataChanged(index(existing, 0), index(existing, ColumnCount - 1));
        return;
    }
    const auto pos =
        std::lower_bound(m_devices.begin(), m_devices.end(), info.slave,
                         [](const DeviceInfo& d, int slave) { return d.slave < slave; });
    const int row = int(pos - m_devices.begin());
    beginInsertRows({}, row, row);
    m_devices.insert(row, info);
    endInsertRows();
}

void BusListModel::remove(int slave)
{
    const int row = rowOf(slave);
    if (row < 0)
        return;
    beginRemoveRows({}, row, row);
    m_devices.remove(row);
    m_reported.remove(slave);
    endRemoveRows();
}

void BusListModel::clear()
{
    beginResetModel();
    m_devices.clear();
    m_reported.clear();
    endResetModel();
}

const DeviceInfo* BusListModel::device(int row) const
{
    return row >= 0 && row < m_devices.size() ? &m_devices[row] : nullptr;
}

int BusListModel::slaveAt(int row) const
{
    const DeviceInfo* d = device(row);
    return d ? d->slave : 0;
}

int BusListModel::rowOf(int slave) const
{
    for (int i = 0; i < m_devices.size(); ++i) {
        if (m_devices[i].slave == slave)
            return i;
    }
    return -1;
}

void BusListModel::statusChanged(int slave)
{
    const int row = rowOf(slave);
    if (row >= 0)
        reportIfChanged(row);
}

BusListModel::Look BusListModel::lookOf(const DeviceInfo& d) const
{
    const DriveStatus s = status(d.slave);
    Look look;
    look.state = display(d, State).toString();
    look.priority = display(d, Priority).toString();
    look.light = StatusLight::color(s, shownLed(d.slave)).rgba();
    look.stale = isStale(d.slave);
    look.failing = s.consecutiveFailures > 0;
    return look;
}

void BusListModel::reportIfChanged(int row)
{
    const DeviceInfo& d = m_devices[row];
    Look look = lookOf(d);
    const auto it = m_reported.find(d.slave);
    if (it != m_reported.end() && *it == look)
        return;
    m_reported.insert(d.slave, std::move(look));
    emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

} // namespace opentop
