#include "model/eol/GoldenMeasure.h"

#include <cmath>

namespace opentop {

GoldenMeasure::GoldenMeasure(ModbusClient* client, const ProfileRegistry& registry,
                             const Recipe& recipe, const GoldenLimits::Margin& margin,
                             QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
    , m_recipe(recipe)
    , m_margin(margin)
{
}

QStringList GoldenMeasure::motionText(const Recipe& recipe)
{
    QStringList lines;
    for (const RecipePosition& p : recipe.positions) {
        QStringList steps;
        double seconds = 0; // every wait to its timeout, every hold, every stop
        for (const RecipeStep& s : p.steps) {
            steps << Recipe::stepTitle(s.type);
            seconds += s.type == RecipeStep::Type::WaitSpeed ? s.timeout
                       : s.type == RecipeStep::Type::Hold    ? s.duration
                       : s.type == RecipeStep::Type::Stop    ? s.deceleration.value_or(0) + s.margin
                                                             : 0.0;
        }
        lines << tr("machine number %1 (%2): runs its motor for about %3 s: %4")
                     .arg(p.machineNumber)
                     .arg(p.variants.isEmpty() ? p.family : p.variants.join(QStringLiteral("/")))
                     .arg(std::ceil(seconds))
                     .arg(steps.join(QStringLiteral(" → ")));
    }
    return lines;
}

void GoldenMeasure::start(const EolStepRunner::Timing& timing, Done done)
{
    EolRun::Options options;
    options.serial = tr("golden unit");
    options.station = tr("recipe from a golden unit");
    options.operatorName = qEnvironmentVariable("USER");
    options.timing = timing;
    m_run = new EolRun(m_client, m_registry, m_recipe, options, this);
    connect(m_run, &EolRun::phaseChanged, this, &GoldenMeasure::phaseChanged);
    connect(m_run, &EolRun::measured, this, &GoldenMeasure::measured);
    m_run->start([this, done](const UnitRecord& record) {
        Outcome outcome;
        outcome.record = record;
        outcome.unconfirmedStops = m_run->unconfirmedStops();
        m_run->deleteLater();
        const std::optional<GoldenLimits::Result> limits =
            GoldenLimits(m_registry).derive(m_recipe, record, m_margin, &outcome.error);
        if (limits) {
            outcome.ok = true;
            outcome.limits = *limits;
            outcome.limits.recipe.description =
                (m_recipe.description.isEmpty() ? QString()
                                                : m_recipe.description + QLatin1Char(' ')) +
                GoldenLimits::description(m_margin, record.started);
        }
        done(outcome);
    });
}

void GoldenMeasure::cancel(const QString& reason)
{
    if (m_run)
        m_run->cancel(reason);
}

void GoldenMeasure::connectionLost(const QString& error)
{
    if (m_run)
        m_run->connectionLost(error);
}

} // namespace opentop
