#include "model/eol/Recipe.h"

#include "model/eol/RecipeStepKinds.h"

namespace opentop {

const RecipePosition* Recipe::position(int machineNumber) const
{
    for (const RecipePosition& p : positions) {
        if (p.machineNumber == machineNumber)
            return &p;
    }
    return nullptr;
}

QString Recipe::stepTypeName(RecipeStep::Type type)
{
    const RecipeStepKinds::Kind* k = RecipeStepKinds::of(type);
    return k ? QString::fromLatin1(k->name) : QString();
}

std::optional<RecipeStep::Type> Recipe::stepTypeFromName(const QString& name)
{
    const RecipeStepKinds::Kind* k = RecipeStepKinds::of(name);
    return k ? std::optional<RecipeStep::Type>(k->type) : std::nullopt;
}

QStringList Recipe::stepTypeNames()
{
    QStringList names;
    for (const RecipeStepKinds::Kind& k : RecipeStepKinds::all())
        names << QString::fromLatin1(k.name);
    return names;
}

QString Recipe::stepTitle(RecipeStep::Type type)
{
    return RecipeStepKinds::title(type);
}

QString Recipe::sourceName(RecipeUnitValue::Source source)
{
    return source == RecipeUnitValue::Source::Csv ? QStringLiteral("csv")
                                                  : QStringLiteral("operator");
}

std::optional<RecipeUnitValue::Source> Recipe::sourceFromName(const QString& name)
{
    if (name == QLatin1String("csv"))
        return RecipeUnitValue::Source::Csv;
    if (name == QLatin1String("operator"))
        return RecipeUnitValue::Source::Operator;
    return std::nullopt;
}

QStringList Recipe::statistics()
{
    return {QStringLiteral("min"), QStringLiteral("mean"), QStringLiteral("max"),
            QStringLiteral("value")};
}

QString Recipe::positionText(int index, int machineNumber)
{
    return tr("position %1 (machine number %2)").arg(index + 1).arg(machineNumber);
}

QString Recipe::passedName(RecipeRetest::Passed passed)
{
    switch (passed) {
    case RecipeRetest::Passed::Technician:
        return QStringLiteral("technician");
    case RecipeRetest::Passed::Refuse:
        return QStringLiteral("refuse");
    case RecipeRetest::Passed::Allow:
        return QStringLiteral("allow");
    }
    return QString();
}

std::optional<RecipeRetest::Passed> Recipe::passedFromName(const QString& name)
{
    for (auto p : {RecipeRetest::Passed::Technician, RecipeRetest::Passed::Refuse,
                   RecipeRetest::Passed::Allow})
        if (passedName(p) == name)
            return p;
    return std::nullopt;
}

} // namespace opentop
