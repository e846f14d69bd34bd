#include "model/eol/RecipeFile.h"
#include "model/io/InputFile.h"

#include "model/eol/RecipeParser.h"
#include "model/files/BackupFile.h"
#include "model/io/OutputFile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>

namespace opentop {

namespace {

// A scalar exactly as QJsonDocument writes it, so that the pretty text and the canonical
// compact text (the checksum's input) hold the same numbers.
QByteArray scalar(const QJsonValue& value)
{
    const QByteArray wrapped = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return wrapped.mid(1, wrapped.size() - 2);
}

// Keys in the order people read them; anything else follows alphabetically.
QStringList orderedKeys(const QJsonObject& object)
{
    static const char* const order[] = {
        "format",        "formatVersion", "product",       "revision",    "description",
        "serialPattern", "serialExample", "machineNumber", "name",        "family",
        "variants",      "variantProof",  "firmware",      "type",        "parameter",
        "statistic",     "spno",          "speed",         "direction",   "target",
        "tolerance",     "value",         "min",           "max",         "lower",
        "upper",         "equals",        "unit",          "timeout",     "duration",
        "deceleration",  "margin",        "source",        "settings",    "unitValues",
        "steps",         "limits",        "positions",     "maxAttempts", "passedSerial",
        "retest",        "checksum"};
    QStringList keys;
    for (const char* k : order) {
        if (object.contains(QLatin1String(k)))
            keys << QString::fromLatin1(k);
    }
    for (const QString& k : object.keys()) {
        if (!keys.contains(k))
            keys << k;
    }
    return keys;
}

bool isFlat(const QJsonValue& value)
{
    if (value.isArray()) {
        const QJsonArray a = value.toArray();
        return std::all_of(a.begin(), a.end(),
                           [](const QJsonValue& v) { return !v.isArray() && !v.isObject(); });
    }
    if (value.isObject()) {
        const QJsonObject o = value.toObject();
        return std::all_of(o.begin(), o.end(), [](const QJsonValue& v) { return isFlat(v); });
    }
    return true;
}

// Indented text with one setting, per-unit value, limit or simple step per line.
QByteArray pretty(const QJsonValue& value, int indent)
{
    const QByteArray inner(indent + 2, ' ');
    const bool flat = isFlat(value);
    if (value.isArray()) {
        QByteArrayList items;
        for (const QJsonValue& v : value.toArray())
            items << (flat ? QByteArray() : inner) + pretty(v, indent + 2);
        if (flat || items.isEmpty())
            return '[' + items.join(", ") + ']';
        return "[\n" + items.join(",\n") + '\n' + QByteArray(indent, ' ') + ']';
    }
    if (value.isObject()) {
        const QJsonObject o = value.toObject();
        QByteArrayList fields;
        for (const QString& k : orderedKeys(o))
            fields << (flat ? QByteArray() : inner) + scalar(k) + ": " +
                          pretty(o.value(k), indent + 2);
        if (flat)
            return '{' + fields.join(", ") + '}';
        return "{\n" + fields.join(",\n") + '\n' + QByteArray(indent, ' ') + '}';
    }
    return scalar(value);
}

void insertOptional(QJsonObject& o, const char* key, const std::optional<double>& v)
{
    if (v)
        o.insert(QLatin1String(key), *v);
}

void insertText(QJsonObject& o, const char* key, const QString& v)
{
    if (!v.isEmpty())
        o.insert(QLatin1String(key), v);
}

QJsonObject limitObject(const RecipeLimit& l, bool withParameter)
{
    QJsonObject o;
    if (withParameter) {
        o.insert(QStringLiteral("parameter"), l.parameter);
        o.insert(QStringLiteral("statistic"), l.statistic);
    }
    insertOptional(o, "lower", l.lower);
    insertOptional(o, "upper", l.upper);
    o.insert(QStringLiteral("unit"), l.unit);
    return o;
}

QJsonObject stepObject(const RecipeStep& s)
{
    QJsonObject o{{QStringLiteral("type"), Recipe::stepTypeName(s.type)}};
    switch (s.type) {
    case RecipeStep::Type::Priority:
    case RecipeStep::Type::NoAlarm:
        break;
    case RecipeStep::Type::Select:
        o.insert(QStringLiteral("spno"), s.spno);
        break;
    case RecipeStep::Type::Speed:
        o.insert(QStringLiteral("speed"), s.speed);
        insertText(o, "unit", s.unit);
        break;
    case RecipeStep::Type::Start:
        o.insert(QStringLiteral("direction"), s.direction);
        break;
    case RecipeStep::Type::WaitSpeed:
        insertOptional(o, "target", s.target);
        o.insert(QStringLiteral("tolerance"), s.tolerance);
        insertText(o, "unit", s.unit);
        o.insert(QStringLiteral("timeout"), s.timeout);
        break;
    case RecipeStep::Type::Hold: {
        o.insert(QStringLiteral("duration"), s.duration);
        QJsonArray limits;
        for (const RecipeLimit& l : s.limits)
            limits << limitObject(l, true);
        o.insert(QStringLiteral("limits"), limits);
        break;
    }
    case RecipeStep::Type::Stop:
        insertOptional(o, "deceleration", s.deceleration);
        o.insert(QStringLiteral("margin"), s.margin);
        break;
    case RecipeStep::Type::Read: {
        const RecipeLimit limit = s.limits.value(0);
        o.insert(QStringLiteral("parameter"), limit.parameter);
        if (!s.equals.isEmpty()) {
            o.insert(QStringLiteral("equals"), s.equals);
        } else {
            const QJsonObject l = limitObject(limit, false);
            for (auto it = l.begin(); it != l.end(); ++it)
                o.insert(it.key(), it.value());
        }
        break;
    }
    }
    return o;
}

QJsonObject positionObject(const RecipePosition& p)
{
    QJsonArray settings;
    for (const RecipeSetting& s : p.settings) {
        QJsonObject o{{QStringLiteral("name"), s.name}, {QStringLiteral("value"), s.value}};
        insertText(o, "unit", s.unit);
        settings << o;
    }
    QJsonArray unitValues;
    for (const RecipeUnitValue& u : p.unitValues) {
        QJsonObject o{{QStringLiteral("name"), u.name},
                      {QStringLiteral("min"), u.min},
                      {QStringLiteral("max"), u.max},
                      {QStringLiteral("source"), Recipe::sourceName(u.source)}};
        insertText(o, "unit", u.unit);
        unitValues << o;
    }
    QJsonArray steps;
    for (const RecipeStep& s : p.steps)
        steps << stepObject(s);
    QJsonObject o{{QStringLiteral("machineNumber"), p.machineNumber},
                  {QStringLiteral("family"), p.family},
                  {QStringLiteral("settings"), settings},
                  {QStringLiteral("steps"), steps}};
    insertText(o, "name", p.name);
    // Empty optional lists are left out, so that a file read and written again is the same.
    if (!p.variants.isEmpty())
        o.insert(QStringLiteral("variants"), QJsonArray::fromStringList(p.variants));
    if (!p.firmware.isEmpty())
        o.insert(QStringLiteral("firmware"), QJsonArray::fromStringList(p.firmware));
    insertText(o, "variantProof", p.variantProof);
    if (!unitValues.isEmpty())
        o.insert(QStringLiteral("unitValues"), unitValues);
    return o;
}

} // namespace

QJsonObject RecipeFile::toObject(const Recipe& recipe)
{
    QJsonArray positions;
    for (const RecipePosition& p : recipe.positions)
        positions << positionObject(p);
    QJsonObject root{{QStringLiteral("format"), formatName()},
                     {QStringLiteral("formatVersion"), kFormatVersion},
                     {QStringLiteral("product"), recipe.product},
                     {QStringLiteral("revision"), recipe.revision},
                     {QStringLiteral("positions"), positions}};
    insertText(root, "description", recipe.description);
    // Left out when empty (any serial), so that older files keep their checksums.
    insertText(root, "serialPattern", recipe.serialPattern);
    insertText(root, "serialExample", recipe.serialExample);
    // Left out when it is the default, so that older files keep their checksums.
    if (recipe.retest != RecipeRetest()) {
        QJsonObject retest{
            {QStringLiteral("maxAttempts"), recipe.retest.maxAttempts},
            {QStringLiteral("passedSerial"), Recipe::passedName(recipe.retest.passed)}};
        root.insert(QStringLiteral("retest"), retest);
    }
    return root;
}

QString RecipeFile::checksumOf(const Recipe& recipe)
{
    return BackupFile::checksumOf(toObject(recipe));
}

QByteArray RecipeFile::toJson(const Recipe& recipe)
{
    QJsonObject root = toObject(recipe);
    root.insert(QStringLiteral("checksum"), BackupFile::checksumOf(root));
    return pretty(root, 0) + '\n';
}

std::optional<Recipe> RecipeFile::fromJson(const QByteArray& data, QString* error,
                                           QString* checksum)
{
    return RecipeParser().parse(data, error, checksum);
}

std::optional<Recipe> RecipeFile::fromEdited(QJsonObject document, QString* error)
{
    // What an editor holds is the person's own text: read it exactly as a file, signed as is.
    document.remove(QStringLiteral("checksum"));
    document.insert(QStringLiteral("checksum"), BackupFile::checksumOf(document));
    return fromJson(QJsonDocument(document).toJson(QJsonDocument::Compact), error);
}

bool RecipeFile::save(const Recipe& recipe, const QString& path, QString* error)
{
    return OutputFile::write(path, toJson(recipe), error);
}

std::optional<Recipe> RecipeFile::load(const QString& path, QString* error, QString* checksum)
{
    QByteArray data;
    const InputFile::Status read = InputFile::read(path, kMaxFileBytes, &data, error);
    if (read == InputFile::Status::CannotOpen)
        return std::nullopt;
    if (read == InputFile::Status::TooLarge) {
        if (error)
            *error = tr("%1 is larger than %2 MB, the most a recipe file may hold; not a recipe "
                        "file")
                         .arg(path)
                         .arg(kMaxFileBytes / (1024 * 1024));
        return std::nullopt;
    }
    const std::optional<Recipe> recipe = fromJson(data, error, checksum);
    if (!recipe && error)
        *error = tr("%1: %2").arg(path, *error);
    return recipe;
}

} // namespace opentop
