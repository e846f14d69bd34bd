#pragma once

#include "model/files/BackupFile.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <optional>

namespace opentop {

class ProfileRegistry;

// Reads a backup file's text and refuses, with the reason, anything that is not an intact
// backup of known drives whose values their profiles allow. Used by BackupFile::fromJson.
class BackupFileParser
{
    Q_DECLARE_TR_FUNCTIONS(opentop::BackupFileParser)
public:
    explicit BackupFileParser(const ProfileRegistry& registry);

    std::optional<BackupFile> parse(const QByteArray& data, QString* error);

private:
    bool checkHeader(const QJsonObject& root);
    bool readDevice(const QJsonObject& object, const QString& where, BackupDevice* device);
    bool readParameter(const Profile& profile, const QJsonObject& object, const QString& where,
                       BackupParameter* parameter);
    bool checkValues(const Profile& profile, const BackupDevice& device, const QString& where,
                     const QJsonArray& parameters);
    bool fail(const QString& message);

    const ProfileRegistry& m_registry;
    QString m_error;
};

} // namespace opentop
