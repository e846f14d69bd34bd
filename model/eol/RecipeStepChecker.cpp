#include "model/eol/RecipeStepChecker.h"

#include "model/profile/Profile.h"
#include "model/profile/ValueCodec.h"

#include <algorithm>

namespace opentop {

RecipeStepChecker::RecipeStepChecker(const Profile& profile, const RecipePosition& position,
                                     QString path, QString where)
    : m_profile(profile)
    , m_position(position)
    , m_path(std::move(path))
    , m_where(std::move(where))
    , m_variants(RecipeChecker::variantsOf(profile, position))
{
}

void RecipeStepChecker::report(const QString& suffix, const QString& message)
{
    *m_problems << RecipeProblem{m_stepPath + suffix, tr("%1: %2").arg(m_stepWhere, message)};
}

const ParameterMeta* RecipeStepChecker::roleParameter(const char* role) const
{
    const ProfileRole* r = m_profile.role(QString::fromLatin1(role));
    return r ? m_profile.parameter(r->parameter) : nullptr;
}

QString RecipeStepChecker::unitOf(const ParameterMeta& meta, const QString& variant) const
{
    return meta.specFor(RecipeChecker::contextOf(m_profile, m_position, variant)).canonicalUnit;
}

bool RecipeStepChecker::needsRole(const char* role)
{
    if (m_profile.role(QString::fromLatin1(role)))
        return true;
    report(QStringLiteral(".type"), tr("a %1 cannot do this step").arg(m_profile.name));
    return false;
}

void RecipeStepChecker::check(QVector<RecipeProblem>* problems)
{
    m_problems = problems;
    bool running = false;
    bool priority = !m_profile.role(QStringLiteral("motionPriority"));
    for (int i = 0; i < m_position.steps.size(); ++i) {
        const RecipeStep& step = m_position.steps.at(i);
        m_stepPath = QStringLiteral("%1.steps[%2]").arg(m_path).arg(i);
        m_stepWhere =
            tr("%1, step %2 (%3)").arg(m_where).arg(i + 1).arg(Recipe::stepTitle(step.type));
        checkStep(step);
        switch (step.type) {
        case RecipeStep::Type::Priority:
            priority = true;
            break;
        case RecipeStep::Type::Start:
        case RecipeStep::Type::Speed:
            if (!priority)
                report(QStringLiteral(".type"),
                       tr("the drive takes motion commands only with communication priority; "
                          "put a priority step before it"));
            running = true;
            break;
        case RecipeStep::Type::WaitSpeed:
        case RecipeStep::Type::Hold:
            if (!running)
                report(QStringLiteral(".type"),
                       tr("the motor is not running here; put a start step before it"));
            break;
        case RecipeStep::Type::Stop:
            running = false;
            break;
        default:
            break;
        }
    }
    if (running)
        *m_problems << RecipeProblem{m_path + QStringLiteral(".steps"),
                                     tr("%1: the steps leave the motor running; end them with "
                                        "a stop step")
                                         .arg(m_where)};
}

void RecipeStepChecker::checkSeconds(double seconds, double max, const QString& field,
                                     const QString& what)
{
    if (!(seconds > 0) || seconds > max)
        report(QLatin1Char('.') + field,
               tr("%1 %2 s is not sane; give more than 0 s and at most %3 s")
                   .arg(what, QString::number(seconds), QString::number(max)));
}

void RecipeStepChecker::checkSpeedUnit(const QString& unit, const QString& field)
{
    const ParameterMeta* speed = roleParameter("currentSpeed");
    if (!speed || unit.isEmpty())
        return;
    for (const QString& variant : m_variants) {
        const QString expected = unitOf(*speed, variant);
        if (unit != expected) {
            report(QLatin1Char('.') + field,
                   tr("unit \"%1\", but %2 is measured in \"%3\"")
                       .arg(unit, RecipeChecker::labelOf(m_profile, speed->name), expected));
            return;
        }
    }
}

void RecipeStepChecker::checkStep(const RecipeStep& step)
{
    switch (step.type) {
    case RecipeStep::Type::Priority:
        needsRole("motionPriority");
        return;
    case RecipeStep::Type::NoAlarm:
        needsRole("alarmActive");
        return;
    case RecipeStep::Type::Select: {
        if (!needsRole("select"))
            return;
        const ParameterMeta* meta = roleParameter("select");
        // The same numbering as RunControl's "select N": running data N is raw value N - 1.
        const QString error =
            meta ? ValueCodec::checkRaw(*meta, step.spno - 1,
                                        RecipeChecker::contextOf(m_profile, m_position, {}))
                 : tr("the profile's selection parameter is missing");
        if (!error.isEmpty())
            report(QStringLiteral(".spno"), tr("running data %1: %2").arg(step.spno).arg(error));
        return;
    }
    case RecipeStep::Type::Speed: {
        if (!needsRole("speedCommand"))
            return;
        const ParameterMeta* meta = roleParameter("speedCommand");
        if (!meta)
            return;
        for (const QString& controlling : meta->controllingParameters()) {
            const bool set =
                std::any_of(m_position.settings.begin(), m_position.settings.end(),
                            [&](const RecipeSetting& s) { return s.name == controlling; });
            if (!set) {
                report(QStringLiteral(".speed"),
                       tr("what %1 means depends on %2, which the recipe does not set; add it "
                          "to the settings")
                           .arg(RecipeChecker::labelOf(m_profile, meta->name),
                                RecipeChecker::labelOf(m_profile, controlling)));
                return;
            }
        }
        if (step.speed == 0) {
            report(QStringLiteral(".speed"), tr("a speed of 0 stops the motor; use a stop step"));
            return;
        }
        for (const QString& variant : m_variants) {
            const ValueContext context = RecipeChecker::contextOf(m_profile, m_position, variant);
            const ValueCodec::Encoded e = ValueCodec::encodeNumber(*meta, step.speed, context);
            if (!e.ok) {
                report(QStringLiteral(".speed"),
                       e.error + RecipeChecker::forVariant(m_profile, m_position, variant));
                return;
            }
            const QString unit = meta->specFor(context).canonicalUnit;
            if (!step.unit.isEmpty() && step.unit != unit) {
                report(QStringLiteral(".unit"),
                       tr("unit \"%1\", but with these settings %2 is in \"%3\"")
                           .arg(step.unit, RecipeChecker::labelOf(m_profile, meta->name), unit));
                return;
            }
        }
        return;
    }
    case RecipeStep::Type::Start:
        if (needsRole("start"))
            needsRole(step.direction == QLatin1String("ccw") ? "ccw" : "cw");
        return;
    case RecipeStep::Type::WaitSpeed:
        if (!needsRole("currentSpeed"))
            return;
        if (!step.target && !m_profile.role(QStringLiteral("targetSpeed")))
            report(
                QStringLiteral(".target"),
                tr("a %1 does not report its target speed; give the target").arg(m_profile.name));
        if (step.target && !(*step.target > 0))
            report(QStringLiteral(".target"), tr("the target speed must be above 0"));
        if (!(step.tolerance > 0) || (step.target && step.tolerance >= *step.target))
            report(QStringLiteral(".tolerance"),
                   tr("the tolerance %1 must be above 0 and below the target speed")
                       .arg(step.tolerance));
        checkSpeedUnit(step.unit, QStringLiteral("unit"));
        checkSeconds(step.timeout, RecipeChecker::kMaxStepSeconds, QStringLiteral("timeout"),
                     tr("the time to reach the speed"));
        return;
    case RecipeStep::Type::Hold:
        checkSeconds(step.duration, RecipeChecker::kMaxStepSeconds, QStringLiteral("duration"),
                     tr("the hold time"));
        if (step.limits.isEmpty())
            report(QStringLiteral(".limits"), tr("the step measures nothing; give limits"));
        for (int i = 0; i < step.limits.size(); ++i)
            checkLimit(step.limits.at(i), QStringLiteral(".limits[%1]").arg(i));
        return;
    case RecipeStep::Type::Stop:
        if (!needsRole("stop"))
            return;
        checkSeconds(step.margin, RecipeChecker::kMaxMarginSeconds, QStringLiteral("margin"),
                     tr("the margin"));
        if (!step.deceleration && !m_profile.role(QStringLiteral("decelerations")))
            report(QStringLiteral(".deceleration"),
                   tr("a %1 has no deceleration time setting to wait for; give the deceleration "
                      "(0 s when it brakes at once)")
                       .arg(m_profile.name));
        if (step.deceleration &&
            (*step.deceleration < 0 || *step.deceleration > RecipeChecker::kMaxStepSeconds))
            report(QStringLiteral(".deceleration"),
                   tr("the deceleration time %1 s is not sane; give 0–%2 s")
                       .arg(*step.deceleration)
                       .arg(RecipeChecker::kMaxStepSeconds));
        return;
    case RecipeStep::Type::Read:
        checkRead(step);
        return;
    }
}

void RecipeStepChecker::checkLimit(const RecipeLimit& limit, const QString& at)
{
    const ParameterMeta* meta = m_profile.parameter(limit.parameter);
    if (!meta || !meta->isReadable()) {
        report(at + QStringLiteral(".parameter"),
               tr("the %1 has no readable value \"%2\"").arg(m_profile.name, limit.parameter));
        return;
    }
    const QString label = RecipeChecker::labelOf(m_profile, limit.parameter);
    if (!meta->isNumeric()) {
        report(at + QStringLiteral(".parameter"), tr("%1 is not a number").arg(label));
        return;
    }
    const bool read = at.isEmpty(); // a read step's one limit
    const bool known = read ? limit.statistic == QLatin1String("value")
                            : Recipe::statistics().contains(limit.statistic) &&
                                  limit.statistic != QLatin1String("value");
    if (!known) {
        report(
            at + QStringLiteral(".statistic"),
            tr("%1: \"%2\" is not a statistic; use min, mean or max").arg(label, limit.statistic));
        return;
    }
    for (const QString& variant : m_variants) {
        const QString unit = unitOf(*meta, variant);
        if (limit.unit != unit) {
            report(at + QStringLiteral(".unit"),
                   tr("%1: the limit's unit is \"%2\", but the value is measured in \"%3\"")
                       .arg(label, limit.unit, unit));
            return;
        }
    }
    if (limit.lower && limit.upper && *limit.lower > *limit.upper)
        report(at + QStringLiteral(".upper"),
               tr("%1: the lower limit %2 %4 is above the upper limit %3 %4")
                   .arg(label)
                   .arg(*limit.lower)
                   .arg(*limit.upper)
                   .arg(limit.unit));
}

void RecipeStepChecker::checkRead(const RecipeStep& step)
{
    const RecipeLimit limit = step.limits.value(0);
    const ParameterMeta* meta = m_profile.parameter(limit.parameter);
    if (!meta || !meta->isReadable()) {
        report(QStringLiteral(".parameter"),
               tr("the %1 has no readable value \"%2\"").arg(m_profile.name, limit.parameter));
        return;
    }
    if (step.equals.isEmpty()) {
        checkLimit(limit, QString());
        return;
    }
    if (meta->isNumeric() && meta->spec.options.isEmpty() && meta->conditions.isEmpty()) {
        report(QStringLiteral(".equals"),
               tr("%1 is a number; compare it with lower and upper limits")
                   .arg(RecipeChecker::labelOf(m_profile, limit.parameter)));
        return;
    }
    if (meta->type == DataType::String)
        return;
    for (const QString& variant : m_variants) {
        const ValueCodec::Encoded e = ValueCodec::encodeText(
            *meta, step.equals, RecipeChecker::contextOf(m_profile, m_position, variant));
        if (!e.ok) {
            report(QStringLiteral(".equals"),
                   e.error + RecipeChecker::forVariant(m_profile, m_position, variant));
            return;
        }
    }
}

} // namespace opentop
