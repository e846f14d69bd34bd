#pragma once

#include "model/eol/Recipe.h"
#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <optional>

namespace opentop {

class ProfileRegistry;

// Limits from a golden unit's measured values: the hold steps' limits of a recipe, tightened
// around what the golden unit measured under the same steps. A limit moves to the measured
// value plus a margin (a share of the value, at least a share of the parameter's full scale),
// rounded outward to the parameter's resolution, and only ever inwards: a derived limit never
// allows more than the recipe's default did, so a speed held at a target keeps its tolerance.
// Pure: the measuring run is GoldenMeasure's; this only computes.
class GoldenLimits
{
    Q_DECLARE_TR_FUNCTIONS(opentop::GoldenLimits)
public:
    struct Margin
    {
        double relative = 0.25;  // of the measured value
        double fullScale = 0.05; // of the parameter's full scale, the least margin
    };
    // One limit that changed (or was kept because the default is already tighter).
    struct Change
    {
        int machineNumber = 0;
        int step = 0;     // index into the position's steps
        QString quantity; // "Load factor max", the record's words
        QString unit;
        int decimals = 0; // the parameter's resolution
        double measured = 0;
        RecipeLimit before;
        RecipeLimit after;
        bool changed() const { return before.lower != after.lower || before.upper != after.upper; }
    };
    struct Result
    {
        Recipe recipe;
        QVector<Change> changes;
    };

    explicit GoldenLimits(const ProfileRegistry& registry);

    // The recipe with derived limits. Fails, naming why, when the measured record is not a
    // pass (a golden unit that fails its own test gives no limits) or lacks a limit's value.
    std::optional<Result> derive(const Recipe& recipe, const UnitRecord& measured,
                                 const Margin& margin, QString* error) const;
    // One line for the recipe's description: when, and with which margin.
    static QString description(const Margin& margin, const QDateTime& measuredAt);
    // "Load factor max ≤ 38 % (default ≤ 100 %, measured 30.0 %)"
    static QString changeText(const Change& change);
    static QString limitText(const RecipeLimit& limit, int decimals, const QString& unit);

private:
    const ProfileRegistry& m_registry;
};

} // namespace opentop
