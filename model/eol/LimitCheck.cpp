#include "model/eol/LimitCheck.h"

#include "model/profile/ParamValue.h"
#include "model/profile/Profile.h"

#include <algorithm>

namespace opentop {

LimitCheck::LimitCheck(const QVector<RecipeLimit>& limits)
    : m_limits(limits)
{
}

void LimitCheck::add(const QHash<QString, ParamValue>& values)
{
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        Stats& s = m_stats[it.key()];
        const double v = it.value().number;
        s.min = s.count ? std::min(s.min, v) : v;
        s.max = s.count ? std::max(s.max, v) : v;
        s.sum += v;
        ++s.count;
    }
}

LimitCheck::Verdict LimitCheck::judge(const Profile& profile, const ValueContext& context) const
{
    Verdict verdict;
    for (const RecipeLimit& l : m_limits) {
        const ParameterMeta* meta = profile.parameter(l.parameter);
        const Stats s = m_stats.value(l.parameter);
        if (!s.count) {
            if (verdict.failure.isEmpty())
                verdict.failure = tr("%1 could not be read").arg(meta ? meta->label : l.parameter);
            continue;
        }
        Check c;
        c.quantity =
            QStringLiteral("%1 %2").arg(meta ? meta->canonicalLabel : l.parameter, l.statistic);
        c.unit = meta ? meta->specFor(context).canonicalUnit : QString();
        c.value = l.statistic == QLatin1String("min")   ? s.min
                  : l.statistic == QLatin1String("max") ? s.max
                                                        : s.sum / s.count;
        c.lower = l.lower;
        c.upper = l.upper;
        c.pass = within(c.value, l.lower, l.upper);
        if (!c.pass && verdict.failure.isEmpty())
            verdict.failure =
                tr("%1 %2 %3, %4")
                    .arg(c.quantity, number(c.value), c.unit, allowedText(l.lower, l.upper, c.unit))
                    .simplified();
        verdict.checks << c;
    }
    return verdict;
}

QString LimitCheck::number(double v)
{
    return QString::number(v, 'g', 6);
}

bool LimitCheck::within(double v, std::optional<double> lower, std::optional<double> upper)
{
    return (!lower || v >= *lower) && (!upper || v <= *upper);
}

QString LimitCheck::allowedText(std::optional<double> lower, std::optional<double> upper,
                                const QString& unit)
{
    QString text;
    if (lower && upper)
        text = tr("allowed %1–%2 %3").arg(number(*lower), number(*upper), unit);
    else if (upper)
        text = tr("allowed at most %1 %2").arg(number(*upper), unit);
    else if (lower)
        text = tr("allowed at least %1 %2").arg(number(*lower), unit);
    return text.trimmed();
}

} // namespace opentop
