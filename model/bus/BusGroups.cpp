#include "model/bus/BusGroups.h"

#include "model/bus/DriveName.h"
#include "model/profile/Profile.h"

#include <QCoreApplication>
#include <algorithm>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::BusGroups", text);
}

const QString kGroupRole = QStringLiteral("group");

} // namespace

QString BusGroups::groupParameter(const Profile& profile)
{
    const ProfileRole* role = profile.role(kGroupRole);
    return profile.supportsGroups && role ? role->parameter : QString();
}

std::optional<int> BusGroups::groupFromRaw(qint64 raw)
{
    if (raw >= 1 && raw <= 247)
        return int(raw);
    return std::nullopt;
}

void BusGroups::clear()
{
    m_groups.clear();
}

void BusGroups::addDrive(int slave)
{
    if (!m_groups.contains(slave))
        m_groups.insert(slave, std::nullopt);
}

void BusGroups::setGroup(int slave, std::optional<int> group)
{
    m_groups.insert(slave, group);
}

QVector<int> BusGroups::drives() const
{
    QVector<int> out(m_groups.keyBegin(), m_groups.keyEnd());
    std::sort(out.begin(), out.end());
    return out;
}

std::optional<int> BusGroups::groupOf(int slave) const
{
    return m_groups.value(slave);
}

std::optional<int> BusGroups::parentOf(int child) const
{
    const std::optional<int> group = groupOf(child);
    // A drive in its own group is the parent of that group, not a child.
    if (group && *group != child)
        return group;
    return std::nullopt;
}

QVector<int> BusGroups::childrenOf(int parent) const
{
    QVector<int> out;
    for (int slave : drives())
        if (parentOf(slave) == parent)
            out << slave;
    return out;
}

QVector<BusGroups::Problem> BusGroups::problems() const
{
    QVector<Problem> out;
    for (int slave : drives()) {
        const std::optional<int> parent = parentOf(slave);
        if (!parent)
            continue;
        if (!m_groups.contains(*parent))
            out << Problem{ProblemKind::MissingParent, slave, *parent};
        else if (isParent(slave))
            out << Problem{ProblemKind::Chain, slave, *parent};
    }
    return out;
}

QString BusGroups::listText(const QVector<int>& slaves)
{
    QStringList parts;
    for (int s : slaves)
        parts << QString::number(s);
    return parts.join(QStringLiteral(", "));
}

QString BusGroups::reachText(int slave) const
{
    const QVector<int> children = childrenOf(slave);
    if (children.isEmpty())
        return {};
    return tr("machine number %1 is the parent of communication group %1: what is sent to it is "
              "also executed by %2 (children do not reply)")
        .arg(slave)
        .arg(namedList(children));
}

QString BusGroups::namedList(const QVector<int>& slaves) const
{
    QStringList parts;
    for (int s : slaves)
        parts << DriveName::listed(s, m_names.value(s));
    return parts.join(QStringLiteral(", "));
}

QString BusGroups::namedAndList(const QVector<int>& slaves) const
{
    if (slaves.size() < 2)
        return namedList(slaves);
    return tr("%1 and %2")
        .arg(namedList(slaves.mid(0, slaves.size() - 1)))
        .arg(namedList({slaves.last()}));
}

QString BusGroups::andListText(const QVector<int>& slaves)
{
    if (slaves.size() < 2)
        return listText(slaves);
    return tr("%1 and %2").arg(listText(slaves.mid(0, slaves.size() - 1))).arg(slaves.last());
}

QString BusGroups::alsoReachesText(int slave) const
{
    const QVector<int> children = childrenOf(slave);
    if (children.isEmpty())
        return {};
    return children.size() == 1
               ? tr("This also reaches machine number %1 (the child of communication group %2; "
                    "it executes it without replying).")
                     .arg(namedList(children))
                     .arg(slave)
               : tr("This also reaches machine numbers %1 (the children of communication group "
                    "%2; they execute it without replying).")
                     .arg(namedAndList(children))
                     .arg(slave);
}

QString BusGroups::roleText(int slave) const
{
    QStringList parts;
    if (const std::optional<int> parent = parentOf(slave))
        parts << tr("child of %1").arg(*parent);
    const QVector<int> children = childrenOf(slave);
    if (!children.isEmpty())
        parts << tr("parent of %1").arg(listText(children));
    return parts.isEmpty() ? QStringLiteral("—") : parts.join(QStringLiteral("; "));
}

QString BusGroups::describe(const Problem& problem)
{
    switch (problem.kind) {
    case ProblemKind::Chain:
        return tr("machine number %1 is a child of %2 and itself a parent: a child must not be "
                  "a group parent")
            .arg(problem.slave)
            .arg(problem.group);
    case ProblemKind::MissingParent:
        return tr("machine number %1 is in communication group %2, but no drive %2 is known: "
                  "frames to %2 reach %1 although nothing answers")
            .arg(problem.slave)
            .arg(problem.group);
    }
    return {};
}

} // namespace opentop
