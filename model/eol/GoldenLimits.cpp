#include "model/eol/GoldenLimits.h"

#include "model/eol/RecipeChecker.h"
#include "model/profile/ProfileRegistry.h"

#include <QLocale>
#include <cmath>

namespace opentop {

namespace {

// Outward to the parameter's resolution, so that the measured value itself always passes.
double roundDown(double value, int decimals)
{
    const double f = std::pow(10.0, decimals);
    return std::floor(value * f + 1e-9) / f;
}

double roundUp(double value, int decimals)
{
    const double f = std::pow(10.0, decimals);
    return std::ceil(value * f - 1e-9) / f;
}

double fullScaleOf(const ValueSpec& spec)
{
    double low = 0;
    double high = 0;
    for (const ValueRange& r : spec.ranges) {
        low = std::min(low, r.min * spec.scale);
        high = std::max(high, r.max * spec.scale);
    }
    return high - low;
}

QString variantOf(const UnitRecord& record, const RecipePosition& position)
{
    for (const UnitDrive& d : record.drives)
        if (d.machineNumber == position.machineNumber && !d.variant.isEmpty())
            return d.variant;
    return position.variants.value(0);
}

QString number(double value, int decimals)
{
    return QLocale::c().toString(value, 'f', decimals);
}

} // namespace

GoldenLimits::GoldenLimits(const ProfileRegistry& registry)
    : m_registry(registry)
{
}

std::optional<GoldenLimits::Result> GoldenLimits::derive(const Recipe& recipe,
                                                         const UnitRecord& measured,
                                                         const Margin& margin, QString* error) const
{
    auto fail = [error](const QString& why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (!measured.isPass())
        return fail(tr("the golden unit did not pass its own test (%1): no limits can come from "
                       "it")
                        .arg(measured.failureReason.isEmpty() ? unitStatusName(measured.status)
                                                              : measured.failureReason));
    Result result{recipe, {}};
    for (RecipePosition& position : result.recipe.positions) {
        const Profile* profile = m_registry.family(position.family);
        if (!profile)
            return fail(tr("machine number %1: unknown family \"%2\"")
                            .arg(position.machineNumber)
                            .arg(position.family));
        const ValueContext context =
            RecipeChecker::contextOf(*profile, position, variantOf(measured, position));
        // The record lists a drive's measurements in step and limit order; each limit takes
        // the next one of its name.
        QVector<Measurement> values;
        for (const Measurement& m : measured.measurements)
            if (m.machineNumber == position.machineNumber)
                values << m;
        int cursor = 0;
        for (int s = 0; s < position.steps.size(); ++s) {
            RecipeStep& step = position.steps[s];
            if (step.type != RecipeStep::Type::Hold)
                continue;
            for (RecipeLimit& limit : step.limits) {
                const ParameterMeta* meta = profile->parameter(limit.parameter);
                if (!meta)
                    return fail(tr("machine number %1: unknown parameter \"%2\"")
                                    .arg(position.machineNumber)
                                    .arg(limit.parameter));
                const QString quantity =
                    QStringLiteral("%1 %2").arg(meta->canonicalLabel, limit.statistic);
                int found = -1;
                for (int i = cursor; i < values.size() && found < 0; ++i)
                    if (values[i].quantity == quantity)
                        found = i;
                if (found < 0)
                    return fail(tr("machine number %1: the golden unit's %2 was not measured")
                                    .arg(position.machineNumber)
                                    .arg(quantity));
                cursor = found + 1;
                const ValueSpec& spec = meta->specFor(context);
                const double v = values[found].value;
                const double room =
                    std::max(std::abs(v) * margin.relative, fullScaleOf(spec) * margin.fullScale);
                Change change{position.machineNumber, s, quantity, spec.canonicalUnit,
                              spec.decimals,          v, limit,    limit};
                // Only inwards: a default limit that is already tighter stays.
                if (limit.upper)
                    change.after.upper = std::min(*limit.upper, roundUp(v + room, spec.decimals));
                if (limit.lower)
                    change.after.lower = std::max(*limit.lower, roundDown(v - room, spec.decimals));
                limit = change.after;
                result.changes << change;
            }
        }
    }
    return result;
}

QString GoldenLimits::description(const Margin& margin, const QDateTime& measuredAt)
{
    return tr("Hold limits measured on the golden unit on %1: the measured value ± %2 % (at "
              "least %3 % of full scale), never wider than the default limits.")
        .arg(measuredAt.toUTC().toString(Qt::ISODate))
        .arg(margin.relative * 100, 0, 'g', 3)
        .arg(margin.fullScale * 100, 0, 'g', 3);
}

QString GoldenLimits::limitText(const RecipeLimit& limit, int decimals, const QString& unit)
{
    const QString u = unit.isEmpty() ? QString() : QStringLiteral(" ") + unit;
    if (limit.lower && limit.upper)
        return tr("%1–%2%3").arg(number(*limit.lower, decimals), number(*limit.upper, decimals), u);
    if (limit.upper)
        return tr("≤ %1%2").arg(number(*limit.upper, decimals), u);
    if (limit.lower)
        return tr("≥ %1%2").arg(number(*limit.lower, decimals), u);
    return tr("no limit");
}

QString GoldenLimits::changeText(const Change& change)
{
    const QString unit = change.unit.isEmpty() ? QString() : QStringLiteral(" ") + change.unit;
    const QString measured = number(change.measured, change.decimals + 1) + unit;
    if (!change.changed())
        return tr("%1 %2 (kept: measured %3)")
            .arg(change.quantity, limitText(change.after, change.decimals, change.unit), measured);
    return tr("%1 %2 (default %3, measured %4)")
        .arg(change.quantity, limitText(change.after, change.decimals, change.unit),
             limitText(change.before, change.decimals, change.unit), measured);
}

} // namespace opentop
