#pragma once

#include "model/eol/Recipe.h"
#include "model/profile/ValueContext.h"

#include <QCoreApplication>
#include <QVector>

namespace opentop {

class Profile;
class ProfileRegistry;
struct ParameterMeta;

// One thing wrong with a recipe: where (machine-readable, "positions[1].settings[3].value")
// and why, in words that name the drive and the setting by its label ("position 2 (machine
// number 5): setting 'SPno2 acceleration time': 99 s is not allowed; allowed: 0.5–30.0 s").
struct RecipeProblem
{
    QString path;
    QString message;
};

// Validates a recipe against the device profiles before anything is sent: every name known for
// the position's family, every value allowed for every allowed variant (through ValueCodec, with
// the recipe's own controlling settings, and DependentValues' rule that a controlling setting
// comes with the settings that depend on it), per-unit ranges inside what the drive allows,
// limits consistent with the measured value's unit, times sane, machine numbers unique, and
// steps the family can do (RecipeStepChecker). An empty list: the recipe may be run.
class RecipeChecker
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RecipeChecker)
public:
    static constexpr double kMaxStepSeconds = 600; // wait, hold, deceleration
    static constexpr double kMaxMarginSeconds = 60;

    explicit RecipeChecker(const ProfileRegistry& registry);

    QVector<RecipeProblem> check(const Recipe& recipe) const;
    // A per-unit value given for a unit (from a CSV or typed by the operator): empty when the
    // recipe has this per-unit value at `machineNumber` and `value` lies in its range and suits
    // the drive; otherwise why not, naming the position and the setting.
    QString checkUnitValue(const Recipe& recipe, int machineNumber, const QString& parameter,
                           double value) const;

    // The variants a position's values must suit: its allowed variants, every variant of the
    // family when it names none, or one empty entry for a family without variants.
    static QStringList variantsOf(const Profile& profile, const RecipePosition& position);
    // The context in which the position's values are validated for `variant`: controlling
    // values (the control mode, the speed mode) come from the recipe's own settings, and
    // messages name parameters by their quoted labels.
    static ValueContext contextOf(const Profile& profile, const RecipePosition& position,
                                  const QString& variant);
    // "'SPno2 speed'"
    static QString labelOf(const Profile& profile, const QString& parameter);
    // " (for DBU400-D4)" when the position's values are checked for several variants.
    static QString forVariant(const Profile& profile, const RecipePosition& position,
                              const QString& variant);

private:
    void checkPosition(const Recipe& recipe, int index, QVector<RecipeProblem>* problems) const;
    void checkSettings(const Profile& profile, const RecipePosition& position, const QString& path,
                       const QString& where, QVector<RecipeProblem>* problems) const;
    void checkUnitValues(const Profile& profile, const RecipePosition& position,
                         const QString& path, const QString& where,
                         QVector<RecipeProblem>* problems) const;
    // The parameter as a setting a recipe may write; empty when it may, else why not.
    QString settingProblem(const Profile& profile, const QString& name) const;
    QString rangeProblem(const Profile& profile, const RecipePosition& position,
                         const RecipeUnitValue& value) const;

    const ProfileRegistry& m_registry;
};

} // namespace opentop
