#pragma once

#include "model/eol/Recipe.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <optional>

namespace opentop {

// A recipe file (docs/recipe-format.md): versioned JSON with a checksum over the canonical
// compact JSON, computed exactly like a backup file's (BackupFile::checksumOf). Reading refuses,
// with the reason naming the entry, anything that is not an intact recipe of this format;
// whether its values suit the drives is RecipeChecker's question.
class RecipeFile
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RecipeFile)
public:
    static constexpr int kFormatVersion = 1;
    // load() refuses larger files without reading them (an eight-drive recipe is about 20 kB).
    static constexpr qint64 kMaxFileBytes = 4 * 1024 * 1024;
    static QString formatName() { return QStringLiteral("opentop-recipe"); }

    // The document without its checksum.
    static QJsonObject toObject(const Recipe& recipe);
    // "sha256:<hex>": what the file of this recipe carries, and what a result record names.
    static QString checksumOf(const Recipe& recipe);
    // The file's text: indented JSON with the checksum.
    static QByteArray toJson(const Recipe& recipe);
    // *checksum (optional) gets the file's checksum when it is accepted.
    static std::optional<Recipe> fromJson(const QByteArray& data, QString* error,
                                          QString* checksum = nullptr);
    // A document edited in the program (the recipe editor), read exactly as a file would be but
    // without a checksum to match: every structural problem is refused with its path.
    static std::optional<Recipe> fromEdited(QJsonObject document, QString* error);
    // Atomic: the file is replaced only once the whole text has been written (OutputFile).
    static bool save(const Recipe& recipe, const QString& path, QString* error);
    static std::optional<Recipe> load(const QString& path, QString* error,
                                      QString* checksum = nullptr);
};

} // namespace opentop
