#pragma once

#include "model/bus/BusGroups.h"
#include "model/session/GroupReach.h"

#include <QObject>
#include <QSet>
#include <QVector>
#include <functional>

namespace opentop {

class BusDrives;

// The communication groups of the bus the program is connected to, kept up to date: every
// DBU's group setting is read when it is identified and whenever a read or write brings a new
// value. It is every session's GroupReach: a write to a parent is validated by its children and
// read back from them by the session itself (ReachedDrives), since they execute it too without
// replying (TROY manual 11-3); after a command (not readable) every value known of the children
// is read again, so their values are read, not assumed.
class BusGroupTracker : public GroupReach
{
    Q_OBJECT
public:
    // Made a child of `drives`, so that whoever has a drive's session can find it (of()).
    explicit BusGroupTracker(BusDrives* drives);

    // The tracker of the bus `object` (a DeviceSession or DeviceParameters of BusDrives)
    // belongs to, or nullptr.
    static BusGroupTracker* of(const QObject* object);

    BusDrives* drives() const { return m_drives; }
    const BusGroups& groups() const { return m_groups; }
    // Whether the drive's group setting has been read (a drive without groups: always).
    bool isKnown(int slave) const { return !m_unread.contains(slave); }
    // Reads the group setting of every drive that has one; `done` once all answered.
    void readAll(std::function<void(int failed)> done = {});
    QString groupParameterOf(int slave) const;
    // GroupReach: the sessions of the known children of `slave`.
    QVector<DeviceSession*> reachedBy(int slave) const override;

signals:
    void groupsChanged();
    // After a command (not readable) to `parent`, every value known so far of its children has
    // been read again. (A setting is read back from them by the write itself.)
    void childrenReread(int parent, const QVector<int>& children, const QStringList& names);

private:
    void track(int slave);
    void onWritten(int parent, const QString& name);

    BusDrives* m_drives;
    BusGroups m_groups;
    QSet<int> m_attached; // sessions whose signals are connected
    QSet<int> m_unread;   // drives with a group setting not read yet
};

} // namespace opentop
