#include "model/eol/RecipeParser.h"

#include "model/eol/RecipeStepKinds.h"

#include "model/eol/RecipeFile.h"
#include "model/eol/SerialRule.h"
#include "model/files/BackupFile.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>
#include <cmath>

namespace opentop {

namespace {

// At most this many entries in any list: far more than any unit has, and it keeps a hostile
// file from making the reader and the checker work for minutes.
constexpr int kMaxEntries = 1000;

QString key(const char* name)
{
    return QString::fromLatin1(name);
}

} // namespace

bool RecipeParser::fail(const QString& message)
{
    if (m_error.isEmpty())
        m_error = message;
    return false;
}

std::optional<Recipe> RecipeParser::parse(const QByteArray& data, QString* error, QString* checksum)
{
    m_error.clear();
    auto refuse = [&](const QString& message) -> std::optional<Recipe> {
        fail(message);
        if (error)
            *error = m_error;
        return std::nullopt;
    };
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(data, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return refuse(tr("not a JSON file: %1 at byte %2")
                          .arg(parseError.errorString())
                          .arg(parseError.offset));
    if (!document.isObject())
        return refuse(tr("not an OpenTOP recipe file: the JSON is not an object"));
    const QJsonObject root = document.object();
    QString sum;
    if (!checkHeader(root, &sum))
        return refuse(m_error);

    Recipe recipe;
    if (!onlyKeys(root, QStringLiteral("the recipe"),
                  {QStringLiteral("format"), QStringLiteral("formatVersion"),
                   QStringLiteral("product"), QStringLiteral("revision"),
                   QStringLiteral("description"), QStringLiteral("serialPattern"),
                   QStringLiteral("serialExample"), QStringLiteral("positions"),
                   QStringLiteral("retest"), QStringLiteral("checksum")}))
        return refuse(m_error);
    if (root.contains(QStringLiteral("retest")) && !readRetest(root, &recipe.retest))
        return refuse(m_error);
    if (!text(root, "product", QString(), &recipe.product, true) ||
        !text(root, "revision", QString(), &recipe.revision, true) ||
        !text(root, "description", QString(), &recipe.description, false))
        return refuse(m_error);
    if (!readSerialRule(root, &recipe))
        return refuse(m_error);
    QJsonArray positions;
    if (!array(root, "positions", QString(), &positions))
        return refuse(m_error);
    if (positions.isEmpty())
        return refuse(tr("\"positions\": the recipe names no drive"));
    for (int i = 0; i < positions.size(); ++i) {
        RecipePosition position;
        const QString at = QStringLiteral("positions[%1]").arg(i);
        if (!positions.at(i).isObject())
            return refuse(tr("%1: must be an object").arg(at));
        if (!readPosition(positions.at(i).toObject(), i, &position))
            return refuse(m_error);
        recipe.positions << position;
    }
    if (checksum)
        *checksum = sum;
    if (error)
        error->clear();
    return recipe;
}

bool RecipeParser::checkHeader(const QJsonObject& root, QString* checksum)
{
    const QString format = root.value(QStringLiteral("format")).toString();
    if (format != RecipeFile::formatName())
        return fail(root.contains(QStringLiteral("format"))
                        ? tr("not an OpenTOP recipe file (\"format\" is \"%1\", not \"%2\")")
                              .arg(format, RecipeFile::formatName())
                        : tr("not an OpenTOP recipe file (no \"format\": \"%1\")")
                              .arg(RecipeFile::formatName()));
    const QJsonValue version = root.value(QStringLiteral("formatVersion"));
    const double v = version.toDouble(-1);
    if (!version.isDouble() || v != std::floor(v) || v < 1)
        return fail(tr("\"formatVersion\" must be a whole number from 1"));
    if (v > RecipeFile::kFormatVersion)
        return fail(tr("written by a newer OpenTOP (recipe format version %1); this version "
                       "reads recipe format version %2")
                        .arg(v, 0, 'g', 15) // any size: no conversion to an integer type
                        .arg(RecipeFile::kFormatVersion));
    const QString given = root.value(QStringLiteral("checksum")).toString();
    if (!given.startsWith(QLatin1String("sha256:")))
        return fail(tr("the recipe has no checksum (\"checksum\": \"sha256:…\"); it was not "
                       "written by OpenTOP or was changed afterwards"));
    QJsonObject body = root;
    body.remove(QStringLiteral("checksum"));
    *checksum = BackupFile::checksumOf(body);
    if (*checksum != given.toLower())
        return fail(tr("the recipe was changed after it was written (checksum mismatch); "
                       "open and save it with OpenTOP to accept the change"));
    return true;
}

bool RecipeParser::readPosition(const QJsonObject& o, int index, RecipePosition* position)
{
    QString at = QStringLiteral("positions[%1]").arg(index);
    if (!onlyKeys(o, at,
                  {QStringLiteral("machineNumber"), QStringLiteral("name"),
                   QStringLiteral("family"), QStringLiteral("variants"), QStringLiteral("firmware"),
                   QStringLiteral("variantProof"), QStringLiteral("settings"),
                   QStringLiteral("unitValues"), QStringLiteral("steps")}))
        return false;
    const QJsonValue slave = o.value(QStringLiteral("machineNumber"));
    const double n = slave.toDouble(-1);
    if (!slave.isDouble() || n != std::floor(n) || n < 1 || n > 247)
        return fail(tr("%1: \"machineNumber\" must be a machine number 1–247").arg(at));
    position->machineNumber = int(n);
    at = tr("%1 (%2)").arg(at, Recipe::positionText(index, position->machineNumber));
    if (!text(o, "name", at, &position->name, false) ||
        !text(o, "family", at, &position->family, true) ||
        !texts(o, "variants", at, &position->variants) ||
        !texts(o, "firmware", at, &position->firmware) ||
        !text(o, "variantProof", at, &position->variantProof, false))
        return false;
    QJsonArray list;
    if (!array(o, "settings", at, &list))
        return false;
    for (int i = 0; i < list.size(); ++i) {
        RecipeSetting s;
        if (!readSetting(list.at(i).toObject(), QStringLiteral("%1 settings[%2]").arg(at).arg(i),
                         &s))
            return false;
        position->settings << s;
    }
    if (!array(o, "unitValues", at, &list))
        return false;
    for (int i = 0; i < list.size(); ++i) {
        RecipeUnitValue u;
        if (!readUnitValue(list.at(i).toObject(),
                           QStringLiteral("%1 unitValues[%2]").arg(at).arg(i), &u))
            return false;
        position->unitValues << u;
    }
    if (!array(o, "steps", at, &list))
        return false;
    for (int i = 0; i < list.size(); ++i) {
        RecipeStep s;
        if (!readStep(list.at(i).toObject(), QStringLiteral("%1 steps[%2]").arg(at).arg(i), &s))
            return false;
        position->steps << s;
    }
    return true;
}

bool RecipeParser::readSetting(const QJsonObject& o, const QString& at, RecipeSetting* setting)
{
    if (!onlyKeys(o, at,
                  {QStringLiteral("name"), QStringLiteral("value"), QStringLiteral("unit")}) ||
        !text(o, "name", at, &setting->name, true) || !text(o, "unit", at, &setting->unit, false))
        return false;
    setting->value = o.value(QStringLiteral("value"));
    if (!setting->value.isDouble() && !setting->value.isString())
        return fail(tr("%1 (%2): \"value\" must be a number or a text").arg(at, setting->name));
    return true;
}

bool RecipeParser::readUnitValue(const QJsonObject& o, const QString& at, RecipeUnitValue* value)
{
    QString source;
    if (!onlyKeys(o, at,
                  {QStringLiteral("name"), QStringLiteral("min"), QStringLiteral("max"),
                   QStringLiteral("unit"), QStringLiteral("source")}) ||
        !text(o, "name", at, &value->name, true) || !number(o, "min", at, &value->min) ||
        !number(o, "max", at, &value->max) || !text(o, "unit", at, &value->unit, false) ||
        !text(o, "source", at, &source, true))
        return false;
    const std::optional<RecipeUnitValue::Source> s = Recipe::sourceFromName(source);
    if (!s)
        return fail(tr("%1 (%2): \"source\" must be \"csv\" or \"operator\", not \"%3\"")
                        .arg(at, value->name, source));
    value->source = *s;
    return true;
}

bool RecipeParser::readStep(const QJsonObject& o, const QString& at, RecipeStep* step)
{
    QString type;
    if (!text(o, "type", at, &type, true))
        return false;
    const std::optional<RecipeStep::Type> t = Recipe::stepTypeFromName(type);
    if (!t)
        return fail(tr("%1: unknown step type \"%2\"; known: %3")
                        .arg(at, type, Recipe::stepTypeNames().join(QStringLiteral(", "))));
    step->type = *t;
    const QString where = tr("%1 (%2)").arg(at, Recipe::stepTitle(step->type));
    // The keys each type may hold: the step table's (RecipeStepKinds).
    const QStringList keys = RecipeStepKinds::keys(step->type);
    switch (step->type) {
    case RecipeStep::Type::Priority:
    case RecipeStep::Type::NoAlarm:
        return onlyKeys(o, where, keys);
    case RecipeStep::Type::Select: {
        double spno = 0;
        if (!onlyKeys(o, where, keys) || !number(o, "spno", where, &spno))
            return false;
        const RecipeStepKinds::Field& range = RecipeStepKinds::of(step->type)->fields.first();
        if (spno != std::floor(spno) || spno < range.min || spno > range.max)
            return fail(tr("%1: \"spno\" must be a running data number such as 2").arg(where));
        step->spno = int(spno);
        return true;
    }
    case RecipeStep::Type::Speed:
        return onlyKeys(o, where, keys) && number(o, "speed", where, &step->speed) &&
               text(o, "unit", where, &step->unit, false);
    case RecipeStep::Type::Start:
        if (!onlyKeys(o, where, keys) || !text(o, "direction", where, &step->direction, true))
            return false;
        if (step->direction != QLatin1String("cw") && step->direction != QLatin1String("ccw"))
            return fail(tr("%1: \"direction\" must be \"cw\" or \"ccw\"").arg(where));
        return true;
    case RecipeStep::Type::WaitSpeed:
        return onlyKeys(o, where, keys) && optionalNumber(o, "target", where, &step->target) &&
               number(o, "tolerance", where, &step->tolerance) &&
               text(o, "unit", where, &step->unit, false) &&
               number(o, "timeout", where, &step->timeout);
    case RecipeStep::Type::Hold: {
        QJsonArray limits;
        if (!onlyKeys(o, where, keys) || !number(o, "duration", where, &step->duration) ||
            !array(o, "limits", where, &limits))
            return false;
        for (int i = 0; i < limits.size(); ++i) {
            RecipeLimit l;
            if (!readLimit(limits.at(i).toObject(),
                           QStringLiteral("%1 limits[%2]").arg(where).arg(i), true, &l))
                return false;
            step->limits << l;
        }
        return true;
    }
    case RecipeStep::Type::Stop:
        return onlyKeys(o, where, keys) &&
               optionalNumber(o, "deceleration", where, &step->deceleration) &&
               number(o, "margin", where, &step->margin);
    case RecipeStep::Type::Read: {
        RecipeLimit l;
        if (!onlyKeys(o, where, keys) || !text(o, "parameter", where, &l.parameter, true) ||
            !text(o, "equals", where, &step->equals, false))
            return false;
        l.statistic = QStringLiteral("value");
        if (step->equals.isEmpty()) {
            QJsonObject limit = o;
            limit.remove(QStringLiteral("type"));
            limit.remove(QStringLiteral("parameter"));
            if (!readLimit(limit, where, false, &l))
                return false;
        } else if (o.contains(QStringLiteral("lower")) || o.contains(QStringLiteral("upper"))) {
            return fail(tr("%1: give either \"equals\" or limits, not both").arg(where));
        }
        step->limits << l;
        return true;
    }
    }
    return fail(tr("%1: unknown step").arg(where));
}

bool RecipeParser::readLimit(const QJsonObject& o, const QString& at, bool withParameter,
                             RecipeLimit* limit)
{
    QStringList keys{QStringLiteral("lower"), QStringLiteral("upper"), QStringLiteral("unit")};
    if (withParameter)
        keys << QStringLiteral("parameter") << QStringLiteral("statistic");
    if (!onlyKeys(o, at, keys) || !optionalNumber(o, "lower", at, &limit->lower) ||
        !optionalNumber(o, "upper", at, &limit->upper))
        return false;
    if (withParameter && (!text(o, "parameter", at, &limit->parameter, true) ||
                          !text(o, "statistic", at, &limit->statistic, true)))
        return false;
    if (!o.value(QStringLiteral("unit")).isString())
        return fail(tr("%1: \"unit\" must be a text (\"\" for a value without a unit)").arg(at));
    limit->unit = o.value(QStringLiteral("unit")).toString();
    if (!limit->lower && !limit->upper)
        return fail(tr("%1: a limit needs \"lower\", \"upper\" or both").arg(at));
    return true;
}

bool RecipeParser::readSerialRule(const QJsonObject& root, Recipe* recipe)
{
    // Given, each must say something: an empty pattern would read as "any serial".
    if (!text(root, "serialPattern", QString(), &recipe->serialPattern,
              root.contains(QStringLiteral("serialPattern"))) ||
        !text(root, "serialExample", QString(), &recipe->serialExample,
              root.contains(QStringLiteral("serialExample"))))
        return false;
    const QString why = SerialRule::recipeProblem(recipe->serialPattern, recipe->serialExample);
    return why.isEmpty() || fail(why);
}

bool RecipeParser::readRetest(const QJsonObject& root, RecipeRetest* retest)
{
    const QString at = QStringLiteral("retest");
    const QJsonValue v = root.value(at);
    if (!v.isObject())
        return fail(tr("\"retest\" must be an object"));
    const QJsonObject o = v.toObject();
    if (!onlyKeys(o, at, {QStringLiteral("maxAttempts"), QStringLiteral("passedSerial")}))
        return false;
    if (o.contains(QStringLiteral("maxAttempts"))) {
        double n = 0;
        if (!number(o, "maxAttempts", at, &n))
            return false;
        if (n != std::floor(n) || n < 0 || n > 100)
            return fail(tr("retest: \"maxAttempts\" must be a whole number from 0 (no limit) to "
                           "100"));
        retest->maxAttempts = int(n);
    }
    if (o.contains(QStringLiteral("passedSerial"))) {
        QString name;
        if (!text(o, "passedSerial", at, &name, true))
            return false;
        const auto passed = Recipe::passedFromName(name);
        if (!passed)
            return fail(tr("retest: \"passedSerial\" must be technician, refuse or allow, not "
                           "\"%1\"")
                            .arg(name));
        retest->passed = *passed;
    }
    return true;
}

bool RecipeParser::onlyKeys(const QJsonObject& o, const QString& at, const QStringList& allowed)
{
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (!allowed.contains(it.key()))
            return fail(tr("%1: unknown key \"%2\"; allowed: %3")
                            .arg(at, it.key(), allowed.join(QStringLiteral(", "))));
    }
    return true;
}

bool RecipeParser::text(const QJsonObject& o, const char* name, const QString& at, QString* out,
                        bool required)
{
    const QJsonValue v = o.value(key(name));
    const QString prefix = at.isEmpty() ? QString() : at + QStringLiteral(": ");
    if (v.isUndefined() && !required)
        return true;
    if (!v.isString() || (required && v.toString().trimmed().isEmpty()))
        return fail(required ? tr("%1\"%2\" must be a non-empty text").arg(prefix, key(name))
                             : tr("%1\"%2\" must be a text").arg(prefix, key(name)));
    *out = v.toString();
    return true;
}

bool RecipeParser::texts(const QJsonObject& o, const char* name, const QString& at,
                         QStringList* out)
{
    const QJsonValue v = o.value(key(name));
    if (v.isUndefined())
        return true;
    if (!v.isArray() || v.toArray().size() > kMaxEntries)
        return fail(tr("%1: \"%2\" must be a list of texts").arg(at, key(name)));
    for (const QJsonValue& item : v.toArray()) {
        if (!item.isString() || item.toString().trimmed().isEmpty())
            return fail(tr("%1: \"%2\" must be a list of non-empty texts").arg(at, key(name)));
        *out << item.toString();
    }
    return true;
}

bool RecipeParser::number(const QJsonObject& o, const char* name, const QString& at, double* out)
{
    const QJsonValue v = o.value(key(name));
    if (!v.isDouble() || !std::isfinite(v.toDouble()))
        return fail(tr("%1: \"%2\" must be a number").arg(at, key(name)));
    *out = v.toDouble();
    return true;
}

bool RecipeParser::optionalNumber(const QJsonObject& o, const char* name, const QString& at,
                                  std::optional<double>* out)
{
    if (!o.contains(key(name)))
        return true;
    double v = 0;
    if (!number(o, name, at, &v))
        return false;
    *out = v;
    return true;
}

bool RecipeParser::array(const QJsonObject& o, const char* name, const QString& at, QJsonArray* out)
{
    const QJsonValue v = o.value(key(name));
    const QString prefix = at.isEmpty() ? QString() : at + QStringLiteral(": ");
    if (v.isUndefined() && !at.isEmpty()) {
        *out = QJsonArray();
        return true; // a position may leave out settings, unit values or steps
    }
    if (!v.isArray())
        return fail(tr("%1\"%2\" must be a list").arg(prefix, key(name)));
    *out = v.toArray();
    if (out->size() > kMaxEntries)
        return fail(tr("%1\"%2\" has %3 entries; at most %4 are allowed")
                        .arg(prefix, key(name))
                        .arg(out->size())
                        .arg(kMaxEntries));
    for (const QJsonValue& item : *out) {
        if (!item.isObject())
            return fail(tr("%1\"%2\": every entry must be an object").arg(prefix, key(name)));
    }
    return true;
}

} // namespace opentop
