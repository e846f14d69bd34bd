#pragma once

#include "model/eol/Recipe.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <optional>

namespace opentop {

// Reads a recipe file's text (used by RecipeFile::fromJson) and refuses, with a reason naming
// the entry ("positions[1].steps[3] (position 2 (machine number 5), step 4): \"timeout\" must
// be a number"), anything that is not an intact recipe: not JSON, another format, a newer
// version, a changed file (checksum), wrong types, missing or unknown keys (a misspelt "upper"
// must not silently drop a limit).
class RecipeParser
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RecipeParser)
public:
    std::optional<Recipe> parse(const QByteArray& data, QString* error, QString* checksum);

private:
    bool checkHeader(const QJsonObject& root, QString* checksum);
    bool readRetest(const QJsonObject& root, RecipeRetest* retest);
    bool readSerialRule(const QJsonObject& root, Recipe* recipe); // serialPattern, serialExample
    bool readPosition(const QJsonObject& o, int index, RecipePosition* position);
    bool readSetting(const QJsonObject& o, const QString& at, RecipeSetting* setting);
    bool readUnitValue(const QJsonObject& o, const QString& at, RecipeUnitValue* value);
    bool readStep(const QJsonObject& o, const QString& at, RecipeStep* step);
    bool readLimit(const QJsonObject& o, const QString& at, bool withParameter, RecipeLimit* limit);

    bool onlyKeys(const QJsonObject& o, const QString& at, const QStringList& allowed);
    bool text(const QJsonObject& o, const char* key, const QString& at, QString* out,
              bool required);
    bool texts(const QJsonObject& o, const char* key, const QString& at, QStringList* out);
    bool number(const QJsonObject& o, const char* key, const QString& at, double* out);
    bool optionalNumber(const QJsonObject& o, const char* key, const QString& at,
                        std::optional<double>* out);
    bool array(const QJsonObject& o, const char* key, const QString& at, QJsonArray* out);
    bool fail(const QString& message);

    QString m_error;
};

} // namespace opentop
