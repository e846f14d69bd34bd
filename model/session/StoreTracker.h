#pragma once

#include <QObject>
#include <QStringList>

namespace opentop {

class DeviceSession;

// Which store commands a drive needs because settings were written to it and not stored since
// (a DC controller keeps its configuration, PID and preset speeds only until power-off unless
// "store" is written). What a drive has stored cannot be read back, so this is the only way to
// know: every acknowledged write of the session counts, from any page, a restore or a group
// write; a store or reload command clears its group, a block write that stores (the
// configuration frame) too. BusMemory keeps it per bus, so that another run of either program
// knows it (seed()). One per session, a child of it (of()).
class StoreTracker : public QObject
{
    Q_OBJECT
public:
    // The tracker of `session`, made on first use (BusDrives makes it with the session, so that
    // it has seen every write).
    static StoreTracker* of(DeviceSession* session);

    // Store commands ("store.config") in the order they became needed.
    QStringList unstored() const { return m_unstored; }
    bool isUnstored(const QString& storeCommand) const { return m_unstored.contains(storeCommand); }
    // Store commands needed for writes made before this tracker saw them (another run of the
    // program that did not store them, BusMemory).
    void seed(const QStringList& storeCommands);

signals:
    void changed();

private:
    explicit StoreTracker(DeviceSession* session);
    void written(const QString& name);

    DeviceSession* m_session;
    QStringList m_unstored;
};

} // namespace opentop
