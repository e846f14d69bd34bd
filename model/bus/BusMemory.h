#pragma once

#include "ConnectionSettings.h"

#include <QHash>
#include <QMap>
#include <QString>
#include <QVector>

namespace opentop {

class BusDrives;

// The drives last seen on a connection (machine number, device type with the variant, the
// model shown), kept in QSettings per serial port, TCP gateway or simulated bus, so that after
// a reconnection or a restart the program can offer them back instead of starting empty.
class BusMemory
{
public:
    struct Drive
    {
        int slave = 0;
        QString type;    // a device type ProfileRegistry::forDeviceType knows: "dbu200", "dcpid"
        QString model;   // "DBU200-D"
        LineFormat line; // its own line format; unset: the port's
    };

    // "serial:/dev/ttyUSB0", "tcp:10.0.0.5:502", "sim:dbu200@1,dcpid@7"
    static QString key(const ConnectionSettings& settings);
    // The connection as the user knows it: "/dev/ttyUSB0", "10.0.0.5:502", "the simulated bus".
    static QString placeText(const ConnectionSettings& settings);

    // The drives present in `drives`, as they would be remembered.
    static QVector<Drive> present(const BusDrives& drives);
    // Remembers the drives present in `drives` (replacing what was remembered for `key`).
    static void save(const QString& key, const BusDrives& drives);
    static QVector<Drive> load(const QString& key);
    static void forget(const QString& key);
    // The drives as the types to identify at each machine number.
    static QHash<int, QString> types(const QVector<Drive>& drives);
    // The drives' own line formats (the port's left out).
    static QMap<int, LineFormat> lines(const QVector<Drive>& drives);
    // "1 (DBU200-D), 2 (DBU200-D), 7 (DC PID)"
    static QString listText(const QVector<Drive>& drives);
};

} // namespace opentop
