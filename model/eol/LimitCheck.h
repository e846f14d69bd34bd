#pragma once

#include "model/eol/RecipeTypes.h"

#include <QCoreApplication>
#include <QHash>
#include <QString>
#include <QVector>
#include <optional>

namespace opentop {

class Profile;
struct ParamValue;
struct ValueContext;

// Measured values against a recipe step's limits (docs/recipe-format.md, "Steps"): the readings
// of a hold gathered per parameter and judged at its end (each limit's statistic: min, mean or
// max), and the texts every step's verdict shares ("allowed 1475–1525 r/min"). EolStepRunner
// takes the readings and reports the checks.
class LimitCheck
{
    Q_DECLARE_TR_FUNCTIONS(opentop::LimitCheck)
public:
    // One statistic against its limits, as the result records it.
    struct Check
    {
        QString quantity; // "Current speed mean" (the profile's English label)
        double value = 0;
        QString unit;
        std::optional<double> lower;
        std::optional<double> upper;
        bool pass = false;
    };
    struct Verdict
    {
        QVector<Check> checks; // in the order of the limits; none for a value never read
        QString failure;       // the first failure in words; empty: every limit holds
    };

    explicit LimitCheck(const QVector<RecipeLimit>& limits = {});

    // One poll's values by parameter name; every value counts towards its statistics.
    void add(const QHash<QString, ParamValue>& values);
    // The limits against what was read; labels and units from `profile` in `context`.
    Verdict judge(const Profile& profile, const ValueContext& context) const;

    // Enough digits for a limit check to be read back exactly; no trailing zeros.
    static QString number(double v);
    static bool within(double v, std::optional<double> lower, std::optional<double> upper);
    // "allowed 1475–1525 r/min", "allowed at most 80 %", "allowed at least 1450 r/min".
    static QString allowedText(std::optional<double> lower, std::optional<double> upper,
                               const QString& unit);

private:
    struct Stats
    {
        double min = 0, max = 0, sum = 0;
        int count = 0;
    };

    QVector<RecipeLimit> m_limits;
    QHash<QString, Stats> m_stats;
};

} // namespace opentop
