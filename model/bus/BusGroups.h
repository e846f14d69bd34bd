#pragma once

#include <QHash>
#include <QString>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

class Profile;

// The communication groups of a bus (TROY manual 11-3): a drive whose group number G is not its
// own machine number is a child of the drive numbered G. Every write sent to G is also executed
// by its children, which never reply. Pure logic: fed with the known drives and their group
// setting (the profile's "group" role), it says what a frame to a machine number also reaches
// and what is wrong with the setup.
class BusGroups
{
public:
    enum class ProblemKind
    {
        Chain,        // a child that is itself a parent: frames to it reach its own children too
        MissingParent // a child whose group number is no known drive: nothing answers there
    };
    struct Problem
    {
        ProblemKind kind;
        int slave; // the child
        int group; // its group number
    };

    // The parameter holding the group number, or empty when the family has no groups.
    static QString groupParameter(const Profile& profile);
    // A group setting's raw value as a group number: 1–247, otherwise (0xFFFF) disabled.
    static std::optional<int> groupFromRaw(qint64 raw);

    void clear();
    // A drive known on the bus; without a group value it has no group (or it is unknown).
    void addDrive(int slave);
    void removeDrive(int slave) { m_groups.remove(slave); }
    void setGroup(int slave, std::optional<int> group);
    // The raw group setting as read from the drive.
    void setGroupRaw(int slave, qint64 raw) { setGroup(slave, groupFromRaw(raw)); }

    QVector<int> drives() const; // ascending
    bool contains(int slave) const { return m_groups.contains(slave); }
    std::optional<int> groupOf(int slave) const;
    // The drive's parent, when it is a child (group set and not its own number).
    std::optional<int> parentOf(int child) const;
    // The known drives that also execute what is sent to `parent`, ascending.
    QVector<int> childrenOf(int parent) const;
    bool isParent(int slave) const { return !childrenOf(slave).isEmpty(); }
    bool isChild(int slave) const { return parentOf(slave).has_value(); }
    QVector<Problem> problems() const;

    // "3, 5"
    static QString listText(const QVector<int>& slaves);
    // "a write to 1 is also executed by 3, 5 (communication group 1; they do not reply)";
    // empty when `slave` has no children.
    QString reachText(int slave) const;
    // "3 and 5", "3, 5 and 150"
    static QString andListText(const QVector<int>& slaves);
    // What a write or command to `slave` also reaches, for a question before sending it:
    // "This also reaches machine numbers 2 and 150 (the children of communication group 1;
    // they execute it without replying)." Empty when `slave` has no children.
    QString alsoReachesText(int slave) const;
    // The role of a drive for a scan listing: "parent of 3, 5", "child of 1", "—".
    QString roleText(int slave) const;
    static QString describe(const Problem& problem);

    // The users' names of the machines (BusDrives::names): the texts above that name the drives
    // a frame reaches name them with it, "2 (Infeed conveyor 3)" (DriveName::listed).
    void setNames(const QHash<int, QString>& names) { m_names = names; }

private:
    QString namedList(const QVector<int>& slaves) const;
    QString namedAndList(const QVector<int>& slaves) const;

    QHash<int, std::optional<int>> m_groups;
    QHash<int, QString> m_names;
};

} // namespace opentop
