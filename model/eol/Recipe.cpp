#include "eol/Recipe.h"

namespace opentop {

namespace {

struct StepName
{
    RecipeStep::Type type;
    const char* name;
};

constexpr StepName kStepNames[] = {
    {RecipeStep::Type::Priority, "priority"},   {RecipeStep::Type::Select, "select"},
    {RecipeStep::Type::Speed, "speed"},         {RecipeStep::Type::Start, "start"},
    {RecipeStep::Type::WaitSpeed, "waitSpeed"}, {RecipeStep::Type::Hold, "hold"},
    {RecipeStep::Type::NoAlarm, "noAlarm"},     {RecipeStep::Type::Stop, "stop"},
    {RecipeStep::Type::Read, "read"},
};

} // namespace

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
    for (const StepName& s : kStepNames) {
        if (s.type == type)
            return QString::fromLatin1(s.name);
    }
    return {};
}

std::optional<RecipeStep::Type> Recipe::stepTypeFromName(const QString& name)
{
    for (const StepName& s : kStepNames) {
        if (name == QLatin1String(s.name))
            return s.type;
    }
    return std::nullopt;
}

QStringList Recipe::stepTypeNames()
{
    QStringList names;
    for (const StepName& s : kStepNames)
        names << QString::fromLatin1(s.name);
    return names;
}

QString Recipe::stepTitle(RecipeStep::Type type)
{
    switch (type) {
    case RecipeStep::Type::Priority:
        return tr("take communication priority");
    case RecipeStep::Type::Select:
        return tr("select running data");
    case RecipeStep::Type::Speed:
        return tr("set the speed command");
    case RecipeStep::Type::Start:
        return tr("start");
    case RecipeStep::Type::WaitSpeed:
        return tr("wait for speed");
    case RecipeStep::Type::Hold:
        return tr("hold and measure");
    case RecipeStep::Type::NoAlarm:
        return tr("check for alarms and warnings");
    case RecipeStep::Type::Stop:
        return tr("stop");
    case RecipeStep::Type::Read:
        return tr("read and compare");
    }
    return {};
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
