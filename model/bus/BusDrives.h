#pragma once

#include "model/session/DeviceInfo.h"

#include <QHash>
#include <QObject>
#include <QSet>
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
    // The BusDrives a session or parameters of it belong to (their parent), or nullptr.
    static BusDrives* of(const QObject* sessionOrParameters);
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
    // The user said the variant is not known: it is not asked again while connected (values
    // are then checked against every variant, VariantNeed).
    void declineVariant(int slave) { m_variantDeclined.insert(slave); }
    bool variantDeclined(int slave) const { return m_variantDeclined.contains(slave); }
    // The variants set on this bus last time (BusMemory): offered when the variant is asked,
    // never applied without the user (the drive at a number may have been replaced).
    void setRememberedVariants(const QHash<int, QString>& variants) { m_remembered = variants; }
    QString rememberedVariant(int slave) const { return m_remembered.value(slave); }

    // The user's name for the machine at `slave` ("Infeed conveyor 3"), kept per machine
    // number also while no drive answers there; empty removes it. Returns why a name is
    // refused (DriveName::problem), empty when it is taken.
    QString setName(int slave, const QString& name);
    QString name(int slave) const { return m_names.value(slave); }
    // The names remembered for this bus (BusMemory), at connection time.
    void setNames(const QHash<int, QString>& names);
    const QHash<int, QString>& names() const { return m_names; }
    // How messages name the drive: "machine number 1 (Infeed conveyor 3)" (DriveName).
    QString label(int slave) const;
    QString title(int slave) const;  // "Machine number 1 (Infeed conveyor 3)"
    QString listed(int slave) const; // "1 (Infeed conveyor 3)", "1"

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
    // A machine's name was set, changed or removed (driveChanged follows for a listed drive).
    void nameChanged(int slave, const QString& name);

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
    QHash<int, QString> m_names;
    QSet<int> m_variantDeclined;
    QHash<int, QString> m_remembered;
    bool m_linkUp = true;
};

} // namespace opentop
