#include "model/eol/RecipeBuilder.h"

#include "model/eol/RecipeChecker.h"
#include "model/files/BackupFile.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/RunningData.h"
#include "model/profile/ValueCodec.h"

#include <cmath>

namespace opentop {

namespace {

constexpr double kHoldSeconds = 5.0;
constexpr double kStopMarginSeconds = 1.0;
constexpr double kSpeedTolerance = 0.05; // of the target
constexpr double kDcCommandShare = 0.3;  // of the speed command's largest value

std::optional<double> numberOf(const Profile& profile, const RecipePosition& position,
                               const QString& name)
{
    const ParameterMeta* meta = profile.parameter(name);
    if (!meta)
        return std::nullopt;
    for (const RecipeSetting& s : position.settings) {
        if (s.name != name)
            continue;
        if (s.value.isDouble())
            return s.value.toDouble();
        const ValueCodec::Encoded e = ValueCodec::encodeText(
            *meta, s.value.toString(),
            RecipeChecker::contextOf(profile, position, position.variants.value(0)));
        if (e.ok)
            return e.raw * meta->spec.scale;
    }
    return std::nullopt;
}

QString roleParameter(const Profile& profile, const char* role)
{
    const ProfileRole* r = profile.role(QString::fromLatin1(role));
    return r ? r->parameter : QString();
}

RecipeLimit limit(const Profile& profile, const QString& parameter, const char* statistic,
                  std::optional<double> lower, std::optional<double> upper)
{
    const ParameterMeta* meta = profile.parameter(parameter);
    return RecipeLimit{parameter, QString::fromLatin1(statistic), lower, upper,
                       meta ? meta->spec.canonicalUnit : QString()};
}

double rounded(double value, int decimals)
{
    const double f = std::pow(10.0, decimals);
    return std::round(value * f) / f;
}

// Limits for the speed while holding at `target` with `tolerance`.
void speedLimits(const Profile& profile, double target, double tolerance, RecipeStep* hold)
{
    const QString speed = roleParameter(profile, "currentSpeed");
    hold->limits << limit(profile, speed, "min", target - tolerance, std::nullopt)
                 << limit(profile, speed, "mean", target - tolerance, target + tolerance)
                 << limit(profile, speed, "max", std::nullopt, target + tolerance);
}

QVector<RecipeStep> dbuSteps(const Profile& profile, const RecipePosition& position)
{
    int spno = 2;
    for (int n = 2; n <= RunningData::count(profile); ++n) {
        const std::optional<double> v = numberOf(
            profile, position, RunningData::parameter(profile, n, QStringLiteral("speed")));
        if (v && *v > 0) {
            spno = n;
            break;
        }
    }
    const double target =
        numberOf(profile, position, RunningData::parameter(profile, spno, QStringLiteral("speed")))
            .value_or(1000);
    const double accel =
        numberOf(profile, position, RunningData::parameter(profile, spno, QStringLiteral("accel")))
            .value_or(5);
    const std::optional<double> direction = numberOf(
        profile, position, RunningData::parameter(profile, spno, QStringLiteral("direction")));
    const double tolerance = std::max(10.0, std::round(target * kSpeedTolerance));

    QVector<RecipeStep> steps;
    RecipeStep s;
    s.type = RecipeStep::Type::Priority;
    steps << s;
    s = RecipeStep();
    s.type = RecipeStep::Type::Select;
    s.spno = spno;
    steps << s;
    s = RecipeStep();
    s.type = RecipeStep::Type::Start;
    s.direction = direction && *direction != 0 ? QStringLiteral("ccw") : QStringLiteral("cw");
    steps << s;
    s = RecipeStep();
    s.type = RecipeStep::Type::WaitSpeed;
    s.target = target;
    s.tolerance = tolerance;
    if (const ParameterMeta* speed = profile.parameter(roleParameter(profile, "currentSpeed")))
        s.unit = speed->spec.canonicalUnit;
    s.timeout = rounded(accel + 5, 1);
    steps << s;
    s = RecipeStep();
    s.type = RecipeStep::Type::Hold;
    s.duration = kHoldSeconds;
    speedLimits(profile, target, tolerance, &s);
    if (profile.role(QStringLiteral("load")))
        s.limits << limit(profile, roleParameter(profile, "load"), "max", std::nullopt, 100);
    steps << s;
    s = RecipeStep();
    s.type = RecipeStep::Type::Stop;
    s.margin = kStopMarginSeconds;
    steps << s;
    s = RecipeStep();
    s.type = RecipeStep::Type::NoAlarm;
    steps << s;
    return steps;
}

QVector<RecipeStep> dcSteps(const Profile& profile, const RecipePosition& position)
{
    const ParameterMeta* command = profile.parameter(roleParameter(profile, "speedCommand"));
    const ParameterMeta* speed = profile.parameter(roleParameter(profile, "currentSpeed"));
    if (!command)
        return {};
    const ValueSpec& spec = command->specFor(RecipeChecker::contextOf(profile, position, {}));
    double largest = 0;
    for (const ValueRange& r : spec.ranges)
        largest = std::max(largest, r.max * spec.scale);
    const double value = rounded(largest * kDcCommandShare, spec.decimals);

    QVector<RecipeStep> steps;
    RecipeStep s;
    s.type = RecipeStep::Type::Speed;
    s.speed = value;
    s.unit = spec.canonicalUnit;
    steps << s;
    s = RecipeStep();
    s.type = RecipeStep::Type::Hold;
    s.duration = kHoldSeconds;
    if (speed && spec.canonicalUnit == speed->spec.canonicalUnit) {
        // The command is itself a speed (the speed loop): wait for it and hold it.
        const double tolerance = std::max(1.0, std::round(value * kSpeedTolerance * 2));
        RecipeStep wait;
        wait.type = RecipeStep::Type::WaitSpeed;
        wait.target = value;
        wait.tolerance = tolerance;
        wait.unit = spec.canonicalUnit;
        wait.timeout = 10;
        steps << wait;
        speedLimits(profile, value, tolerance, &s);
    } else if (speed) {
        // What speed a duty cycle or current gives depends on the motor: check it turns, and
        // let the engineer tighten the limits on the golden unit.
        s.limits << limit(profile, speed->name, "min", 1, std::nullopt);
    }
    const ProfileRole* monitor = profile.role(QStringLiteral("monitor"));
    for (const QString& name : monitor ? monitor->parameters : QStringList()) {
        const ParameterMeta* meta = profile.parameter(name);
        const bool current = meta && meta->spec.canonicalUnit == QLatin1String("A");
        if (!current && name != roleParameter(profile, "running"))
            continue;
        double max = 0;
        for (const ValueRange& r : meta->spec.ranges)
            max = std::max(max, r.max * meta->spec.scale);
        s.limits << limit(profile, name, "max", std::nullopt, max);
    }
    steps << s;
    s = RecipeStep();
    s.type = RecipeStep::Type::Stop;
    s.deceleration = 0; // a speed command of 0 brakes the motor
    s.margin = kStopMarginSeconds;
    steps << s;
    return steps;
}

} // namespace

RecipeBuilder::RecipeBuilder(const ProfileRegistry& registry)
    : m_registry(registry)
{
}

QVector<RecipeStep> RecipeBuilder::defaultSteps(const Profile& profile,
                                                const RecipePosition& position)
{
    if (profile.role(QStringLiteral("select")) && profile.role(QStringLiteral("start")) &&
        profile.role(QStringLiteral("currentSpeed")))
        return dbuSteps(profile, position);
    if (profile.role(QStringLiteral("speedCommand")))
        return dcSteps(profile, position);
    return {};
}

std::optional<RecipePosition> RecipeBuilder::positionFrom(const BackupDevice& device,
                                                          QString* error) const
{
    const Profile* profile = m_registry.family(device.family);
    if (!profile) {
        if (error)
            *error = tr("%1: unknown family \"%2\"").arg(device.title(), device.family);
        return std::nullopt;
    }
    RecipePosition position;
    position.machineNumber = device.slave;
    position.name = device.name;
    position.family = device.family;
    if (!device.variant.isEmpty())
        position.variants << device.variant;
    if (!device.firmware.isEmpty())
        position.firmware << device.firmware;
    const ProfileRole* communication = profile->role(QStringLiteral("communication"));
    const ValueContext context = device.context(*profile);
    for (const BackupParameter& p : device.parameters) {
        const ParameterMeta* meta = profile->parameter(p.name);
        if (!meta || !meta->backup || (communication && communication->parameters.contains(p.name)))
            continue;
        const ParamValue v = ValueCodec::decode(*meta, p.registers, context);
        if (!v.valid || !v.allowed) {
            if (error)
                *error = tr("%1: %2 holds a value the profile does not allow: %3")
                             .arg(device.title(), meta->label, v.error);
            return std::nullopt;
        }
        RecipeSetting s;
        s.name = p.name;
        if (meta->type == DataType::String || !v.text.isEmpty())
            s.value = v.text;
        else
            s.value = BackupFile::valueOf(*meta, p.registers, context);
        if (s.value.isDouble())
            s.unit = meta->specFor(context).canonicalUnit;
        position.settings << s;
    }
    position.steps = defaultSteps(*profile, position);
    return position;
}

std::optional<Recipe> RecipeBuilder::fromDevices(const QVector<BackupDevice>& devices,
                                                 const QString& product, const QString& revision,
                                                 QString* error) const
{
    Recipe recipe;
    recipe.product = product;
    recipe.revision = revision;
    for (const BackupDevice& d : devices) {
        const std::optional<RecipePosition> p = positionFrom(d, error);
        if (!p)
            return std::nullopt;
        recipe.positions << *p;
    }
    if (recipe.positions.isEmpty()) {
        if (error)
            *error = tr("no drive to make a recipe of");
        return std::nullopt;
    }
    return recipe;
}

std::optional<Recipe> RecipeBuilder::fromBackup(const BackupFile& file, const QString& product,
                                                const QString& revision, QString* error) const
{
    return fromDevices(file.devices, product, revision, error);
}

} // namespace opentop
