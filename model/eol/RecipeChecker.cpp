#include "model/eol/RecipeChecker.h"

#include "model/eol/RecipeStepChecker.h"
#include "model/eol/SerialRule.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DependentValues.h"

#include <QHash>
#include <QRegularExpression>
#include <QSet>
#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

ValueCodec::Encoded encodeValue(const ParameterMeta& meta, const QJsonValue& value,
                                const ValueContext& context)
{
    if (value.isDouble())
        return ValueCodec::encodeNumber(meta, value.toDouble(), context);
    return ValueCodec::encodeText(meta, value.toString(), context);
}

bool isCommunicationSetting(const Profile& profile, const QString& name)
{
    const ProfileRole* role = profile.role(QStringLiteral("communication"));
    return role && role->parameters.contains(name);
}

} // namespace

RecipeChecker::RecipeChecker(const ProfileRegistry& registry)
    : m_registry(registry)
{
}

QStringList RecipeChecker::variantsOf(const Profile& profile, const RecipePosition& position)
{
    if (profile.variants.isEmpty())
        return {QString()};
    if (!position.variants.isEmpty())
        return position.variants;
    QStringList all;
    for (const ProfileVariant& v : profile.variants)
        all << v.id;
    return all;
}

QString RecipeChecker::labelOf(const Profile& profile, const QString& parameter)
{
    const ParameterMeta* meta = profile.parameter(parameter);
    return QStringLiteral("'%1'").arg(meta ? meta->label : parameter);
}

QString RecipeChecker::forVariant(const Profile& profile, const RecipePosition& position,
                                  const QString& variant)
{
    const ProfileVariant* v = profile.variant(variant);
    return v && variantsOf(profile, position).size() > 1 ? tr(" (for %1)").arg(v->model)
                                                         : QString();
}

ValueContext RecipeChecker::contextOf(const Profile& profile, const RecipePosition& position,
                                      const QString& variant)
{
    ValueContext context;
    context.variant = variant;
    const Profile* p = &profile;
    context.displayName = [p](const QString& name) { return labelOf(*p, name); };
    const QVector<RecipeSetting> settings = position.settings;
    context.parameterRaw = [p, settings, variant](const QString& name) -> std::optional<qint64> {
        const ParameterMeta* meta = p->parameter(name);
        for (const RecipeSetting& s : settings) {
            if (s.name != name || !meta)
                continue;
            ValueContext plain;
            plain.variant = variant;
            const ValueCodec::Encoded e = encodeValue(*meta, s.value, plain);
            if (e.ok)
                return qint64(e.raw);
        }
        return std::nullopt;
    };
    return context;
}

QVector<RecipeProblem> RecipeChecker::check(const Recipe& recipe) const
{
    QVector<RecipeProblem> problems;
    if (recipe.product.trimmed().isEmpty())
        problems << RecipeProblem{QStringLiteral("product"), tr("the recipe names no product")};
    if (recipe.revision.trimmed().isEmpty())
        problems << RecipeProblem{QStringLiteral("revision"), tr("the recipe has no revision")};
    if (recipe.positions.isEmpty())
        problems << RecipeProblem{QStringLiteral("positions"), tr("the recipe names no drive")};
    // The file's reader refuses these already; a recipe made in the program is asked here.
    QString field;
    const QString serialProblem =
        SerialRule::recipeProblem(recipe.serialPattern, recipe.serialExample, &field);
    if (!serialProblem.isEmpty())
        problems << RecipeProblem{field, serialProblem};
    QHash<int, int> seen;
    for (int i = 0; i < recipe.positions.size(); ++i) {
        const int n = recipe.positions.at(i).machineNumber;
        if (seen.contains(n))
            problems << RecipeProblem{
                QStringLiteral("positions[%1].machineNumber").arg(i),
                tr("%1: machine number %2 is already position %3; every drive of a unit needs "
                   "its own machine number")
                    .arg(Recipe::positionText(i, n))
                    .arg(n)
                    .arg(seen.value(n) + 1)};
        else
            seen.insert(n, i);
        checkPosition(recipe, i, &problems);
    }
    return problems;
}

void RecipeChecker::checkPosition(const Recipe& recipe, int index,
                                  QVector<RecipeProblem>* problems) const
{
    const RecipePosition& position = recipe.positions.at(index);
    const QString path = QStringLiteral("positions[%1]").arg(index);
    const QString where = Recipe::positionText(index, position.machineNumber);
    const Profile* profile = m_registry.family(position.family);
    if (!profile) {
        *problems << RecipeProblem{
            path + QStringLiteral(".family"),
            tr("%1: unknown family \"%2\"; known: %3")
                .arg(where, position.family, m_registry.families().join(QStringLiteral(", ")))};
        return;
    }
    if (position.machineNumber < profile->minSlave || position.machineNumber > profile->maxSlave)
        *problems << RecipeProblem{path + QStringLiteral(".machineNumber"),
                                   tr("%1: a %2 takes machine numbers %3–%4")
                                       .arg(where, profile->name)
                                       .arg(profile->minSlave)
                                       .arg(profile->maxSlave)};
    QSet<QString> variants;
    for (int v = 0; v < position.variants.size(); ++v) {
        const QString& id = position.variants.at(v);
        const QString at = QStringLiteral("%1.variants[%2]").arg(path).arg(v);
        if (!profile->variant(id)) {
            QStringList known;
            for (const ProfileVariant& pv : profile->variants)
                known << pv.id;
            *problems << RecipeProblem{
                at, tr("%1: the %2 has no variant \"%3\"; known: %4")
                        .arg(where, profile->name, id,
                             known.isEmpty() ? tr("none") : known.join(QStringLiteral(", ")))};
        } else if (variants.contains(id)) {
            *problems << RecipeProblem{at, tr("%1: variant \"%2\" is named twice").arg(where, id)};
        }
        variants.insert(id);
    }
    if (!position.variantProof.isEmpty() && position.variantProof != QLatin1String("required") &&
        position.variantProof != QLatin1String("operator"))
        *problems << RecipeProblem{
            path + QStringLiteral(".variantProof"),
            tr("%1: variantProof \"%2\" is not known; use \"required\" or \"operator\" (or "
               "leave it out)")
                .arg(where, position.variantProof)};
    else if (position.variantProof == QLatin1String("operator") && position.variants.size() != 1)
        *problems << RecipeProblem{path + QStringLiteral(".variantProof"),
                                   tr("%1: variantProof \"operator\" needs exactly one allowed "
                                      "variant for the operator to confirm")
                                       .arg(where)};
    if (variants.size() != position.variants.size() ||
        std::any_of(position.variants.begin(), position.variants.end(),
                    [&](const QString& id) { return !profile->variant(id); }))
        return; // the values cannot be checked for variants that do not exist
    static const QRegularExpression version(QStringLiteral("^[0-9]+\\.[0-9]+$"));
    for (int f = 0; f < position.firmware.size(); ++f) {
        if (!version.match(position.firmware.at(f)).hasMatch())
            *problems << RecipeProblem{
                QStringLiteral("%1.firmware[%2]").arg(path).arg(f),
                tr("%1: firmware version \"%2\" is not a version as the drive reports it "
                   "(major.minor, e.g. \"1.5\")")
                    .arg(where, position.firmware.at(f))};
    }
    checkSettings(*profile, position, path, where, problems);
    checkUnitValues(*profile, position, path, where, problems);
    RecipeStepChecker(*profile, position, path, where).check(problems);
}

QString RecipeChecker::settingProblem(const Profile& profile, const QString& name) const
{
    const ParameterMeta* meta = profile.parameter(name);
    if (!meta)
        return tr("the %1 has no setting \"%2\"").arg(profile.name, name);
    if (!meta->backup)
        return tr("%1 is not a setting a recipe can write").arg(labelOf(profile, name));
    if (isCommunicationSetting(profile, name))
        return tr("%1 decides how the drive communicates; a recipe cannot change it, or the "
                  "station would lose the drive in the middle of the run")
            .arg(labelOf(profile, name));
    return {};
}

void RecipeChecker::checkSettings(const Profile& profile, const RecipePosition& position,
                                  const QString& path, const QString& where,
                                  QVector<RecipeProblem>* problems) const
{
    QSet<QString> names;
    for (const RecipeSetting& s : position.settings)
        names.insert(s.name);
    for (const RecipeUnitValue& u : position.unitValues)
        names.insert(u.name);
    QSet<QString> seen;
    for (int i = 0; i < position.settings.size(); ++i) {
        const RecipeSetting& s = position.settings.at(i);
        const QString at = QStringLiteral("%1.settings[%2]").arg(path).arg(i);
        auto report = [&](const QString& suffix, const QString& message) {
            *problems << RecipeProblem{at + suffix, tr("%1: setting %2").arg(where, message)};
        };
        const QString problem = settingProblem(profile, s.name);
        if (!problem.isEmpty()) {
            *problems << RecipeProblem{at + QStringLiteral(".name"),
                                       tr("%1: %2").arg(where, problem)};
            continue;
        }
        const ParameterMeta& meta = *profile.parameter(s.name);
        const QString label = labelOf(profile, s.name);
        if (seen.contains(s.name)) {
            report(QStringLiteral(".name"), tr("%1 is given twice").arg(label));
            continue;
        }
        seen.insert(s.name);
        bool resolvable = true;
        for (const QString& controlling : meta.controllingParameters()) {
            if (!names.contains(controlling)) {
                report(QStringLiteral(".name"),
                       tr("%1: what it allows depends on %2, which the recipe does not set; "
                          "add %2 to the settings")
                           .arg(label, labelOf(profile, controlling)));
                resolvable = false;
            }
        }
        for (const QString& dependent : DependentValues::of(profile, meta)) {
            if (!names.contains(dependent) && profile.parameter(dependent)->backup)
                report(QStringLiteral(".name"),
                       tr("%1 decides what %2 allows; set %2 in the recipe too, or the drive "
                          "may be left with a value that is no longer valid")
                           .arg(label, labelOf(profile, dependent)));
        }
        if (!resolvable)
            continue;
        for (const QString& variant : variantsOf(profile, position)) {
            const ValueContext context = contextOf(profile, position, variant);
            const ValueCodec::Encoded e = encodeValue(meta, s.value, context);
            if (!e.ok) {
                report(QStringLiteral(".value"), e.error + forVariant(profile, position, variant));
                break;
            }
            const QString unit = meta.specFor(context).canonicalUnit;
            if (!s.unit.isEmpty() && s.unit != unit) {
                report(QStringLiteral(".unit"),
                       tr("%1: unit \"%2\", but the drive's value is in \"%3\"")
                           .arg(label, s.unit, unit));
                break;
            }
        }
    }
}

void RecipeChecker::checkUnitValues(const Profile& profile, const RecipePosition& position,
                                    const QString& path, const QString& where,
                                    QVector<RecipeProblem>* problems) const
{
    QSet<QString> settings;
    for (const RecipeSetting& s : position.settings)
        settings.insert(s.name);
    QSet<QString> seen;
    for (int i = 0; i < position.unitValues.size(); ++i) {
        const RecipeUnitValue& u = position.unitValues.at(i);
        const QString at = QStringLiteral("%1.unitValues[%2]").arg(path).arg(i);
        auto report = [&](const QString& suffix, const QString& message) {
            *problems << RecipeProblem{at + suffix,
                                       tr("%1: per-unit value %2").arg(where, message)};
        };
        const QString problem = settingProblem(profile, u.name);
        if (!problem.isEmpty()) {
            *problems << RecipeProblem{at + QStringLiteral(".name"),
                                       tr("%1: %2").arg(where, problem)};
            continue;
        }
        const QString label = labelOf(profile, u.name);
        if (settings.contains(u.name) || seen.contains(u.name)) {
            report(QStringLiteral(".name"),
                   tr("%1 is given twice (as a setting or as a per-unit value)").arg(label));
            continue;
        }
        seen.insert(u.name);
        if (u.min > u.max) {
            report(QStringLiteral(".max"),
                   tr("%1: the range's lowest value %2 is above its highest value %3")
                       .arg(label)
                       .arg(u.min)
                       .arg(u.max));
            continue;
        }
        const QString range = rangeProblem(profile, position, u);
        if (!range.isEmpty())
            report(QStringLiteral(".min"), range);
    }
}

QString RecipeChecker::rangeProblem(const Profile& profile, const RecipePosition& position,
                                    const RecipeUnitValue& value) const
{
    const ParameterMeta& meta = *profile.parameter(value.name);
    const QString label = labelOf(profile, value.name);
    for (const QString& controlling : meta.controllingParameters()) {
        const bool set = std::any_of(position.settings.begin(), position.settings.end(),
                                     [&](const RecipeSetting& s) { return s.name == controlling; });
        if (!set)
            return tr("%1: what it allows depends on %2, which the recipe does not set")
                .arg(label, labelOf(profile, controlling));
    }
    for (const QString& variant : variantsOf(profile, position)) {
        const ValueContext context = contextOf(profile, position, variant);
        const ValueSpec& spec = meta.specFor(context);
        if (!meta.isNumeric() || (spec.ranges.isEmpty() && !spec.options.isEmpty()))
            return tr("%1 is not a number; a per-unit value needs a numeric setting").arg(label);
        if (!value.unit.isEmpty() && value.unit != spec.canonicalUnit)
            return tr("%1: unit \"%2\", but the drive's value is in \"%3\"")
                .arg(label, value.unit, spec.canonicalUnit);
        const QString unit =
            spec.canonicalUnit.isEmpty() ? QString() : QLatin1Char(' ') + spec.canonicalUnit;
        const QString shown = tr("%1: range %2–%3%4")
                                  .arg(label, ValueCodec::formatNumber(value.min, spec.decimals),
                                       ValueCodec::formatNumber(value.max, spec.decimals), unit);
        for (double end : {value.min, value.max}) {
            const ValueCodec::Encoded e = ValueCodec::encodeNumber(meta, end, context);
            if (!e.ok)
                return tr("%1 is outside what the drive allows: %2%3")
                    .arg(shown, e.error, forVariant(profile, position, variant));
        }
        // Both ends allowed is not enough when the allowed values have a gap (0 or 250–3000).
        const double lo = value.min / spec.scale;
        const double hi = value.max / spec.scale;
        const bool inOne =
            spec.ranges.isEmpty() ||
            std::any_of(spec.ranges.begin(), spec.ranges.end(), [&](const ValueRange& r) {
                return lo >= r.min - 1e-9 && hi <= r.max + 1e-9;
            });
        if (!inOne)
            return tr("%1 includes values the drive does not allow; allowed: %2%3")
                .arg(shown, ValueCodec::allowedText(meta, context),
                     forVariant(profile, position, variant));
    }
    return {};
}

QString RecipeChecker::checkUnitValue(const Recipe& recipe, int machineNumber,
                                      const QString& parameter, double value) const
{
    for (int i = 0; i < recipe.positions.size(); ++i) {
        const RecipePosition& position = recipe.positions.at(i);
        if (position.machineNumber != machineNumber)
            continue;
        const QString where = Recipe::positionText(i, machineNumber);
        const Profile* profile = m_registry.family(position.family);
        for (const RecipeUnitValue& u : position.unitValues) {
            if (u.name != parameter || !profile)
                continue;
            const ParameterMeta* meta = profile->parameter(parameter);
            if (!meta)
                break;
            const QString unit = meta->spec.canonicalUnit.isEmpty()
                                     ? QString()
                                     : QLatin1Char(' ') + meta->spec.canonicalUnit;
            if (!std::isfinite(value) || value < u.min || value > u.max)
                return tr("%1: per-unit value %2: %3%4 is outside the recipe's range %5–%6%4")
                    .arg(where, labelOf(*profile, parameter), QString::number(value), unit,
                         QString::number(u.min), QString::number(u.max));
            for (const QString& variant : variantsOf(*profile, position)) {
                const ValueCodec::Encoded e =
                    ValueCodec::encodeNumber(*meta, value, contextOf(*profile, position, variant));
                if (!e.ok)
                    return tr("%1: per-unit value %2").arg(where, e.error);
            }
            return {};
        }
        return tr("%1: the recipe has no per-unit value %2")
            .arg(where, profile ? labelOf(*profile, parameter) : parameter);
    }
    return tr("the recipe has no drive at machine number %1").arg(machineNumber);
}

} // namespace opentop
