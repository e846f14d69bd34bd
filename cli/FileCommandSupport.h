#pragma once

#include "model/files/BackupFile.h"
#include "model/files/RestorePlan.h"

#include <QJsonArray>
#include <QJsonObject>
#include <optional>

namespace opentop {

class CliContext;

// What backup, restore and compare share: loading a backup file with the refusal printed, the
// JSON forms of plans and register lists, printing JSON.
class FileCommandSupport
{
public:
    // Loads `path`; on failure prints why and sets *exitCode (3 for a refused file, 2 for a file
    // that cannot be read).
    static std::optional<BackupFile> load(CliContext& context, const QString& path, int* exitCode);
    static void printJson(CliContext& context, const QJsonObject& object);
    static QJsonArray registersJson(const QVector<quint16>& registers);
    static QJsonObject planJson(const RestorePlan& plan);
    static QString idList(const QVector<int>& ids); // "1, 7"
};

} // namespace opentop
