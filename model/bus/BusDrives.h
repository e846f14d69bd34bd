#pragma once

#include "session/DeviceInfo.h"

#include <QHash>
#include <QObject>
#include <QVector>

namespace opentop {

class DeviceParameters;
class DeviceSession;
class ModbusClient;
class ProfileRegistry;

// The drives known on the bus the program is connected to: what identification said about
// each, and — for drives of a profiled family — their session and parameters, created once and
// kept while the connection lasts. Scans and "add by number" feed it; the GUI shows it.
class BusDrives : public QObject
{
    Q_OBJECT
public:
    BusDrives(ModbusClient* client, const ProfileRegistry& registry, QObject* parent = nullptr);
    ~BusDrives() override;

    ModbusClient* client() const { return m_client; }
    // Adds or updates a drive. A drive that is present gets a session (kept on later updates).
    void update(const DeviceInfo& info);
    void remove(int slave);
    void clear();

    QVector<int> slaves() const; // ascending
    bool contains(int slave) const { return m_drives.contains(slave); }
    DeviceInfo info(int slave) const;
    DeviceSession* session(int slave) const;       // nullptr unless present and profiled
    DeviceParameters* parameters(int slave) const; // likewise
    // The variant where the drive does not report it (chosen by the user, or the simulated
    // bus's list); changes the allowed values used for its validation.
    void setVariant(int slave, const QString& variant);
    // The drive's own line format (ModbusClient::setDriveLine): requests to it go out in it
    // from now on; unset, or the port's, talks to it at the port's again. A drive not in the
    // list yet keeps it for when it is added. The table outlives remove(): a rescan asks the
    // drive in its format.
    void setLine(int slave, const LineFormat& format);

    // Whether the connection is open: false once it is lost (or could not be opened). Nothing
    // read before counts as live while the link is down (monitor/Freshness).
    bool linkUp() const { return m_linkUp; }
    void setLinkUp(bool up);

signals:
    void driveAdded(int slave);
    void driveChanged(int slave);
    void driveRemoved(int slave);
    void linkChanged(bool up);

private:
    struct Drive
    {
        DeviceInfo info;
        DeviceSession* session = nullptr;
        DeviceParameters* parameters = nullptr;
    };

    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
    QHash<int, Drive> m_drives;
    bool m_linkUp = true;
};

} // namespace opentop
