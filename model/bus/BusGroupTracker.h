#pragma once

#include "bus/BusGroups.h"

#include <QObject>
#include <QSet>
#include <QVector>
#include <functional>

namespace opentop {

class BusDrives;

// The communication groups of the bus the program is connected to, kept up to date: every
// DBU's group setting is read when it is identified and whenever a read or write brings a new
// value; what a drive acknowledges as written is re-read on its children, which executed it
// too without replying (TROY manual 11-3), so their values are read, not assumed.
class BusGroupTracker : public QObject
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

signals:
    void groupsChanged();
    // After a write of `names` to `parent`, its children's values have been read again: the
    // same setting, or after a command every value of theirs known so far.
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
