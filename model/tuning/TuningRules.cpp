#include "model/tuning/TuningRules.h"

#include "model/tuning/TuningSpec.h"

namespace opentop {

namespace {

struct Entry
{
    TuningRules::Rule rule;
    const char* id;
    double kp, ti, td; // of Ku and Tu
    double overshoot;  // % the proposal may overshoot on the model (GainDesign)
};
const Entry kRules[] = {
    {TuningRules::Rule::Soft, "soft", 0.2, 0.5, 1.0 / 3, 2},
    {TuningRules::Rule::Medium, "medium", 0.33, 0.5, 1.0 / 3, 15},
    {TuningRules::Rule::Stiff, "stiff", 0.6, 0.5, 0.125, 30},
    {TuningRules::Rule::TyreusLuyben, "tyreus-luyben", 1 / 2.2, 2.2, 1 / 6.3, 10},
    {TuningRules::Rule::ZieglerNicholsPi, "zn-pi", 0.45, 1 / 1.2, 0, 20},
};

const Entry& entry(TuningRules::Rule rule)
{
    for (const Entry& e : kRules) {
        if (e.rule == rule)
            return e;
    }
    return kRules[1];
}

} // namespace

QStringList TuningRules::ids()
{
    QStringList list;
    for (const Entry& e : kRules)
        list << QString::fromLatin1(e.id);
    return list;
}

std::optional<TuningRules::Rule> TuningRules::fromId(const QString& id)
{
    for (const Entry& e : kRules) {
        if (id.compare(QLatin1String(e.id), Qt::CaseInsensitive) == 0)
            return e.rule;
    }
    return std::nullopt;
}

QString TuningRules::id(Rule rule)
{
    return QString::fromLatin1(entry(rule).id);
}

QString TuningRules::title(Rule rule)
{
    switch (rule) {
    case Rule::Soft:
        return tr("Soft (no overshoot)");
    case Rule::Medium:
        return tr("Medium (some overshoot)");
    case Rule::Stiff:
        return tr("Stiff (Ziegler–Nichols)");
    case Rule::TyreusLuyben:
        return tr("Tyreus–Luyben (robust)");
    case Rule::ZieglerNicholsPi:
        return tr("PI only (Ziegler–Nichols)");
    }
    return {};
}

double TuningRules::overshootBound(Rule rule)
{
    return entry(rule).overshoot;
}

TuningRules::Continuous TuningRules::continuous(Rule rule, double ku, double tuMs)
{
    const Entry& e = entry(rule);
    return {e.kp * ku, e.ti * tuMs, e.td * tuMs};
}

PidGains TuningRules::toController(const Continuous& c, const TuningSpec& spec, int dPeriodMs)
{
    PidGains g;
    g.dPeriodMs = std::max(1, dPeriodMs);
    g.p = c.kp;
    g.i = c.tiMs > 0 ? c.kp * spec.periodMs / c.tiMs : 0;
    g.d = c.kp * c.tdMs / g.dPeriodMs;
    return g;
}

PidGains TuningRules::propose(Rule rule, double ku, double tuMs, const TuningSpec& spec,
                              int dPeriodMs)
{
    return toController(continuous(rule, ku, tuMs), spec, dPeriodMs);
}

} // namespace opentop
