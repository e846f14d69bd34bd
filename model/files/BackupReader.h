#pragma once

#include "model/files/BackupDevice.h"

#include <QObject>
#include <QStringList>
#include <functional>

namespace opentop {

class DeviceSession;

// Reads every setting a backup holds from one drive (the parameters with backup = true, in as
// few requests as the drive allows) and the identification parameters for the file's header.
class BackupReader : public QObject
{
    Q_OBJECT
public:
    struct Result
    {
        bool ok = false; // every setting read and allowed by the profile
        BackupDevice device;
        int parameters = 0; // settings in the backup
        int requests = 0;   // requests sent, fallbacks included
        qint64 elapsedMs = 0;
        QStringList failures;   // "name: reason" for settings that could not be read
        QStringList disallowed; // settings whose value the profile does not allow
    };
    using Done = std::function<void(const Result&)>;

    explicit BackupReader(DeviceSession* session, QObject* parent = nullptr);

    // The settings a backup of `profile` holds, in profile order.
    static QStringList settingNames(const Profile& profile);
    void read(Done done);

private:
    DeviceSession* m_session;
};

} // namespace opentop
