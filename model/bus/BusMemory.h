#pragma once

#include "model/session/DeviceInfo.h"
#include "transport/ConnectionSettings.h"

#include <QDateTime>

#include <QHash>
#include <QMap>
#include <QString>
#include <QVector>

namespace opentop {

class BusDrives;
class DeviceSession;

// The drives last seen on a connection (machine number, device type with the variant, the
// model shown) and the names users gave its machines, kept in QSettings per serial port, TCP
// gateway or simulated bus, so that after a reconnection or a restart the program can offer
// them back instead of starting empty. The window and the command line share them: both read
// and write the window's settings file.
class BusMemory
{
public:
    struct Drive
    {
        int slave = 0;
        QString type;    // a device type ProfileRegistry::forDeviceType knows: "dbu200", "dcpid"
        QString model;   // "DBU200-D"
        QString name;    // the user's name for the machine, empty: none
        LineFormat line; // its own line format; unset: the port's
    };

    // "serial:/dev/ttyUSB0", "tcp:10.0.0.5:502", "sim:dbu200@1,dcpid@7"
    static QString key(const ConnectionSettings& settings);
    // The connection as the user knows it: "/dev/ttyUSB0", "10.0.0.5:502", "the simulated bus".
    static QString placeText(const ConnectionSettings& settings);

    // The drives present in `drives`, as they would be remembered.
    static QVector<Drive> present(const BusDrives& drives);
    // The drives present among a scan's `devices`.
    static QVector<Drive> present(const QVector<DeviceInfo>& devices);
    // Remembers the drives present in `drives` (replacing what was remembered for `key`), and
    // when.
    static void save(const QString& key, const BusDrives& drives);
    static void save(const QString& key, const QVector<Drive>& drives);
    // A scan of machine numbers `from`–`to` found `found`: what was remembered in that range is
    // replaced, the rest kept (a scan of 1–10 says nothing of drive 30).
    static void update(const QString& key, int from, int to, const QVector<Drive>& found);
    static QVector<Drive> load(const QString& key);
    // When the drives of `key` were last saved; invalid when never (or before this was kept).
    static QDateTime savedAt(const QString& key);
    static void forget(const QString& key);
    // The drives as the types to identify at each machine number.
    static QHash<int, QString> types(const QVector<Drive>& drives);
    // The drives' own line formats (the port's left out).
    static QMap<int, LineFormat> lines(const QVector<Drive>& drives);
    // "1 (DBU200-D), 2 (Infeed conveyor 3, DBU200-D), 7 (DC PID)"
    static QString listText(const QVector<Drive>& drives);

    // The names users gave the machines of the bus `key`, by machine number (kept apart from
    // the drives seen: a name stays while its drive is off). Names that would not pass
    // DriveName::problem (a settings file edited by hand) are left out.
    static QHash<int, QString> names(const QString& key);
    // Keeps `name` for machine number `slave` (checked by the caller); empty removes it.
    static void setName(const QString& key, int slave, const QString& name);

    // The store commands the drive at `slave` needs for writes not stored yet (StoreTracker),
    // kept so that a restore run later — after Ctrl-C, a lost link or a crash, also from the
    // other program — still stores them. keep() gives `session`'s tracker what is kept and
    // keeps its changes (once per session).
    static QStringList unstored(const QString& key, int slave);
    static void keep(const QString& key, DeviceSession* session);
};

} // namespace opentop
