#include "model/eol/RecipeStepKinds.h"

namespace opentop {

namespace {

using Field = RecipeStepKinds::Field;
using K = Field::Kind;
using T = RecipeStep::Type;

} // namespace

const QVector<RecipeStepKinds::Kind>& RecipeStepKinds::all()
{
    // In the order a test usually runs them; the editor lists them in this order.
    static const QVector<Kind> kinds{
        {T::Priority, "priority", QT_TR_NOOP("take communication priority"), {}},
        {T::Select,
         "select",
         QT_TR_NOOP("select running data"),
         {{"spno", K::Integer, true, QT_TR_NOOP("Running data:"), "", "", 1, 8}}},
        {T::Speed,
         "speed",
         QT_TR_NOOP("set the speed command"),
         {{"speed", K::Number, true, QT_TR_NOOP("Speed command:"), "", ""},
          {"unit", K::Unit, false, QT_TR_NOOP("Unit:"), "", QT_TR_NOOP("the speed command's unit")}}},
        {T::Start,
         "start",
         QT_TR_NOOP("start"),
         {{"direction", K::Direction, true, QT_TR_NOOP("Direction:"), "", ""}}},
        {T::WaitSpeed,
         "waitSpeed",
         QT_TR_NOOP("wait for speed"),
         {{"target", K::Number, false, QT_TR_NOOP("Target speed:"), "",
           QT_TR_NOOP("empty: the drive's own target speed")},
          {"tolerance", K::Number, true, QT_TR_NOOP("Tolerance (±):"), "", ""},
          {"unit", K::Unit, false, QT_TR_NOOP("Unit:"), "", QT_TR_NOOP("the speed's unit")},
          {"timeout", K::Number, true, QT_TR_NOOP("Within:"), "s", ""}}},
        {T::Hold,
         "hold",
         QT_TR_NOOP("hold and measure"),
         {{"duration", K::Number, true, QT_TR_NOOP("Duration:"), "s", ""},
          {"limits", K::Limits, true, "", "", ""}}},
        {T::Stop,
         "stop",
         QT_TR_NOOP("stop"),
         {{"deceleration", K::Number, false, QT_TR_NOOP("Deceleration time:"), "s",
           QT_TR_NOOP("empty: the drive's setting")},
          {"margin", K::Number, true, QT_TR_NOOP("Margin:"), "s", ""}}},
        {T::NoAlarm, "noAlarm", QT_TR_NOOP("check for alarms and warnings"), {}},
        {T::Read,
         "read",
         QT_TR_NOOP("read and compare"),
         {{"parameter", K::Parameter, true, QT_TR_NOOP("Parameter:"), "", ""},
          {"lower", K::Number, false, QT_TR_NOOP("Lower limit:"), "", QT_TR_NOOP("empty: none")},
          {"upper", K::Number, false, QT_TR_NOOP("Upper limit:"), "", QT_TR_NOOP("empty: none")},
          {"unit", K::Unit, false, QT_TR_NOOP("Unit:"), "", QT_TR_NOOP("the value's unit")},
          {"equals", K::Text, false, QT_TR_NOOP("Or equals:"), "",
           QT_TR_NOOP("the expected text, instead of limits")}}},
    };
    return kinds;
}

const RecipeStepKinds::Kind* RecipeStepKinds::of(RecipeStep::Type type)
{
    for (const Kind& k : all())
        if (k.type == type)
            return &k;
    return nullptr;
}

const RecipeStepKinds::Kind* RecipeStepKinds::of(const QString& name)
{
    for (const Kind& k : all())
        if (name == QLatin1String(k.name))
            return &k;
    return nullptr;
}

QString RecipeStepKinds::title(RecipeStep::Type type)
{
    const Kind* k = of(type);
    return k ? tr(k->title) : QString();
}

QStringList RecipeStepKinds::keys(RecipeStep::Type type)
{
    QStringList keys{QStringLiteral("type")};
    if (const Kind* k = of(type))
        for (const Field& f : k->fields)
            keys << QString::fromLatin1(f.key);
    return keys;
}

QString RecipeStepKinds::fieldLabel(const Field& field)
{
    return *field.label ? tr(field.label) : QString();
}

QString RecipeStepKinds::fieldEmpty(const Field& field)
{
    return *field.empty ? tr(field.empty) : QString();
}

} // namespace opentop
