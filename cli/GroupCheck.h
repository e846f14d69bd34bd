#pragma once

#include "model/bus/BusGroups.h"
#include "model/session/DeviceInfo.h"
#include "model/session/ReachedDrives.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonObject>
#include <QStringList>
#include <QVector>

namespace opentop {

class CliContext;

// Before a write or command to one drive: which other drives execute it too (communication
// groups). The drives asked are the ones the user names on the bus (--bus-drives,
// OPENTOP_BUS_DRIVES) or the simulated bus's list: children never reply, so they cannot be
// found by asking the target.
class GroupCheck
{
public:
    explicit GroupCheck(CliContext& context);

    // Reads the group setting of the target and the known drives and says what a write to
    // `target` also reaches. Returns ExitOk to go on; otherwise the code to exit with, after
    // printing why (nothing was sent). Without `confirmed`, a target with children is refused.
    int before(int target, bool confirmed, int refusalCode);
    // before() in two steps: read the groups (the sessions then know their children), and
    // the question (a target with children needs `confirmed`).
    int read(int target);
    int confirm(int target, bool confirmed, int refusalCode);
    const QVector<int>& children() const { return m_children; }
    const BusGroups& groups() const { return m_groups; }

    struct ChildValue
    {
        int slave = 0;
        QString name;
        QString text;  // the value read back from the child
        QString error; // why it could not be read
        // Compared with what was written: verified, differs, or (neither) not verified.
        bool verified = false;
        bool differs = false;
    };
    // What the write itself read back from the children (DeviceSession::Outcome::reached).
    static QVector<ChildValue> fromOutcome(const QString& name,
                                           const QVector<ReachedDrives::Result>& reached);
    // After the write: reads `names` back from every child (what they hold, not assumed),
    // compared with the registers `expected` of a name where given.
    QVector<ChildValue> readChildren(const QStringList& names,
                                     const QHash<QString, QVector<quint16>>& expected = {});
    void print(const QVector<ChildValue>& values);
    static QJsonArray toJson(const QVector<ChildValue>& values);

    // For scan: the group of each drive found whose family has one (`hasGroups`: read).
    static void readAll(CliContext& context, const QVector<DeviceInfo>& devices, BusGroups* groups,
                        QHash<int, bool>* hasGroups);
    // A scan row's group: "off (parent of 3)", "1 (child of 1)"; empty without a group.
    static QString groupText(const BusGroups& groups, const QHash<int, bool>& hasGroups, int slave);
    // A scan's JSON device: "group" (null: disabled), "parent", "children".
    static void addJson(const BusGroups& groups, const QHash<int, bool>& hasGroups, int slave,
                        QJsonObject* device);

private:
    CliContext& m_context;
    BusGroups m_groups;
    QVector<int> m_children;
};

} // namespace opentop
