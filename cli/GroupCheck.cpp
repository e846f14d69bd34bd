#include "cli/GroupCheck.h"

#include "cli/CliContext.h"
#include "cli/TextTable.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <QCoreApplication>
#include <QJsonObject>

namespace opentop {

namespace {

constexpr qint64 kStaleListS = 24 * 3600; // a day: a remembered list is then said every time

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::GroupCheck", text);
}

// Reads the drive's group setting into `groups`; false when it has none or cannot be read.
bool readGroup(CliContext& context, DeviceSession* session, BusGroups* groups)
{
    const QString parameter = BusGroups::groupParameter(session->profile());
    if (parameter.isEmpty())
        return false;
    DeviceSession::ReadManyOutcome read;
    context.wait([&](std::function<void()> finish) {
        session->readMany({parameter}, [&read, finish](const DeviceSession::ReadManyOutcome& o) {
            read = o;
            finish();
        });
    });
    const ParamValue value = session->cachedValue(parameter);
    if (read.failed > 0 || !value.valid)
        return false;
    groups->setGroupRaw(session->slave(), qint64(value.raw));
    return true;
}

} // namespace

GroupCheck::GroupCheck(CliContext& context)
    : m_context(context)
{
}

int GroupCheck::before(int target, bool confirmed, int refusalCode)
{
    const int code = read(target);
    return code != ExitOk ? code : confirm(target, confirmed, refusalCode);
}

int GroupCheck::read(int target)
{
    QString error;
    DeviceSession* session = m_context.session(target, &error);
    if (!session || BusGroups::groupParameter(session->profile()).isEmpty())
        return ExitOk; // a family without groups: the write reaches the target only
    const std::optional<BusDriveList> listed = m_context.busDrives(&error);
    if (!listed) {
        m_context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitUsage;
    }
    m_groups.addDrive(target);
    readGroup(m_context, session, &m_groups);
    if (listed->source == BusDriveList::Source::None) {
        // Children never reply: without a list, the drives a write also reaches are unknown.
        if (m_context.parser().isSet(QStringLiteral("no-group-check"))) {
            m_context.err() << tr("note: --no-group-check: drives in communication group %1 "
                                  "(which also execute what is sent to %1) were not looked for")
                                   .arg(target)
                            << Qt::endl;
            return ExitOk;
        }
        m_context.err() << tr("error: the drives on this bus are not known, so drives in "
                              "communication group %1 (which also execute what is sent to %1, "
                              "without replying) cannot be named; nothing was sent")
                               .arg(target)
                        << Qt::endl;
        m_context.err() << tr("scan the bus first (opentop-cli scan), name its drives with "
                              "--bus-drives LIST, or add --no-group-check to send it without "
                              "looking")
                        << Qt::endl;
        return ExitUsage;
    }
    QVector<int> others;
    for (int slave : listed->slaves)
        if (slave != target)
            others << slave;
    if (others.isEmpty())
        return ExitOk; // the only drive on the bus
    QVector<int> silent;
    for (int slave : others) {
        DeviceSession* other = m_context.session(slave, &error);
        if (!other) {
            silent << slave;
            continue;
        }
        m_groups.addDrive(slave);
        if (!readGroup(m_context, other, &m_groups) &&
            !BusGroups::groupParameter(other->profile()).isEmpty())
            silent << slave;
    }
    if (!silent.isEmpty())
        m_context.err() << tr("warning: the communication group of %1 could not be read")
                               .arg(BusGroups::listText(silent))
                        << Qt::endl;
    m_context.setGroups(m_groups);
    m_children = m_groups.childrenOf(target);
    // Each remembered drive's group was read again just now; the list itself is said where it
    // matters: when it names children, or when it is old enough that drives may have been added.
    if (listed->source == BusDriveList::Source::Remembered &&
        (!m_children.isEmpty() || !listed->savedAt.isValid() ||
         listed->savedAt.secsTo(QDateTime::currentDateTimeUtc()) > kStaleListS))
        m_context.err() << tr("note: the drives on the bus are %1, from %2; drives added since "
                              "are not known until the next scan")
                               .arg(BusGroups::listText(listed->slaves), listed->sourceText())
                        << Qt::endl;
    return ExitOk;
}

int GroupCheck::confirm(int target, bool confirmed, int refusalCode)
{
    if (m_children.isEmpty())
        return ExitOk;
    m_context.err()
        << (confirmed ? tr("note: %1") : tr("error: %1")).arg(m_groups.reachText(target))
        << Qt::endl;
    if (!confirmed) {
        m_context.err() << tr("add --yes to send it to all of %1 and %2; nothing was sent")
                               .arg(target)
                               .arg(BusGroups::listText(m_children))
                        << Qt::endl;
        return refusalCode;
    }
    return ExitOk;
}

QVector<GroupCheck::ChildValue>
GroupCheck::readChildren(const QStringList& names, const QHash<QString, QVector<quint16>>& expected)
{
    QVector<ChildValue> out;
    for (int child : m_children) {
        QString error;
        DeviceSession* session = m_context.session(child, &error);
        DeviceSession::ReadManyOutcome read;
        if (session)
            m_context.wait([&](std::function<void()> finish) {
                session->readMany(names, [&read, finish](const DeviceSession::ReadManyOutcome& o) {
                    read = o;
                    finish();
                });
            });
        for (const QString& name : names) {
            ChildValue v{child, name, {}, error};
            const DeviceSession::Outcome o = read.results.value(name);
            const ParameterMeta* meta = session ? session->profile().parameter(name) : nullptr;
            if (meta && o.ok && o.value.valid) {
                v.text = ValueCodec::format(*meta, o.value, session->context());
                if (expected.contains(name)) {
                    v.verified = o.value.registers == expected.value(name);
                    v.differs = !v.verified;
                }
            } else if (v.error.isEmpty())
                v.error = o.error.isEmpty() ? tr("not readable") : o.error;
            out << v;
        }
    }
    return out;
}

QVector<GroupCheck::ChildValue>
GroupCheck::fromOutcome(const QString& name, const QVector<ReachedDrives::Result>& reached)
{
    QVector<ChildValue> out;
    for (const ReachedDrives::Result& r : reached) {
        ChildValue v{r.slave, name, r.held, {}, r.verified, r.mismatch};
        if (!r.value.valid)
            v.error = r.text;
        out << v;
    }
    return out;
}

void GroupCheck::print(const QVector<ChildValue>& values)
{
    if (values.isEmpty())
        return;
    m_context.out() << tr("Read back from the drives of the group:") << '\n';
    TextTable table({tr("Drive"), tr("Parameter"), tr("Value"), tr("Result")});
    for (const ChildValue& v : values)
        table.addRow({QString::number(v.slave), v.name,
                      v.error.isEmpty() ? v.text : tr("(not read: %1)").arg(v.error),
                      v.verified  ? tr("verified")
                      : v.differs ? tr("DIFFERS from what was written")
                                  : tr("not verified")});
    table.print(m_context.out());
}

QJsonArray GroupCheck::toJson(const QVector<ChildValue>& values)
{
    QJsonArray out;
    for (const ChildValue& v : values) {
        QJsonObject o{{QStringLiteral("slave"), v.slave}, {QStringLiteral("name"), v.name}};
        if (v.error.isEmpty())
            o.insert(QStringLiteral("text"), v.text);
        else
            o.insert(QStringLiteral("error"), v.error);
        o.insert(QStringLiteral("verified"), v.verified);
        if (v.differs)
            o.insert(QStringLiteral("differs"), true);
        out.append(o);
    }
    return out;
}

void GroupCheck::readAll(CliContext& context, const QVector<DeviceInfo>& devices, BusGroups* groups,
                         QHash<int, bool>* hasGroups)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    for (const DeviceInfo& info : devices) {
        if (info.state != DeviceInfo::State::Present &&
            info.state != DeviceInfo::State::Unidentified)
            continue;
        groups->addDrive(info.slave); // a parent may be any drive that answers
        const Profile* profile = registry.family(info.family);
        if (info.state != DeviceInfo::State::Present || !profile ||
            BusGroups::groupParameter(*profile).isEmpty())
            continue;
        QString error;
        DeviceSession* session = context.session(info.slave, &error);
        if (session && readGroup(context, session, groups))
            hasGroups->insert(info.slave, true);
    }
}

QString GroupCheck::groupText(const BusGroups& groups, const QHash<int, bool>& hasGroups, int slave)
{
    if (!hasGroups.value(slave) && !groups.isParent(slave))
        return QString();
    const std::optional<int> group = groups.groupOf(slave);
    const QString number = !hasGroups.value(slave) ? QStringLiteral("?")
                           : group                 ? QString::number(*group)
                                                   : tr("off");
    const QString role = groups.roleText(slave);
    return role == QStringLiteral("—") ? number : QStringLiteral("%1 (%2)").arg(number, role);
}

void GroupCheck::addJson(const BusGroups& groups, const QHash<int, bool>& hasGroups, int slave,
                         QJsonObject* device)
{
    if (hasGroups.value(slave)) {
        const std::optional<int> group = groups.groupOf(slave);
        device->insert(QStringLiteral("group"), group ? QJsonValue(*group) : QJsonValue());
        if (const std::optional<int> parent = groups.parentOf(slave))
            device->insert(QStringLiteral("parent"), *parent);
    }
    QJsonArray children;
    for (int child : groups.childrenOf(slave))
        children.append(child);
    if (!children.isEmpty())
        device->insert(QStringLiteral("children"), children);
}

} // namespace opentop
