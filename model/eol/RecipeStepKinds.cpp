#include "model/eol/RecipeStepKinds.h"

#include "model/profile/Profile.h"

#include <QJsonArray>

namespace opentop {

namespace {

using Field = RecipeStepKinds::Field;
using K = Field::Kind;
using T = RecipeStep::Type;

// A number as given (text that is not one is shown as typed, for the checker to name).
QString numberText(const QJsonValue& v)
{
    if (v.isDouble())
        return QString::number(v.toDouble(), 'g', 12);
    return v.toString();
}

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
          {"unit", K::Unit, false, QT_TR_NOOP("Unit:"), "",
           QT_TR_NOOP("the speed command's unit")}}},
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

QString RecipeStepKinds::summary(const QJsonObject& s, const Profile* profile)
{
    const Kind* kind = of(s.value(QStringLiteral("type")).toString());
    if (!kind)
        return QString();
    const QString unit = s.value(QStringLiteral("unit")).toString();
    auto n = [&s](const char* key) { return numberText(s.value(QLatin1String(key))); };
    auto withUnit = [&unit](const QString& text) {
        return unit.isEmpty() ? text : text + QLatin1Char(' ') + unit;
    };
    switch (kind->type) {
    case T::Priority:
    case T::NoAlarm:
        return QString();
    case T::Select:
        return tr("SPno%1").arg(n("spno"));
    case T::Speed:
        return tr("to %1").arg(withUnit(n("speed")));
    case T::Start:
        return s.value(QStringLiteral("direction")).toString().toUpper();
    case T::WaitSpeed:
        return tr("%1 ± %2 within %3 s")
            .arg(s.contains(QStringLiteral("target")) ? n("target")
                                                      : tr("the drive's target speed"),
                 withUnit(n("tolerance")), n("timeout"));
    case T::Hold:
        return tr("for %1 s; limits: %2")
            .arg(n("duration"))
            .arg(s.value(QStringLiteral("limits")).toArray().size());
    case T::Stop:
        return s.contains(QStringLiteral("deceleration"))
                   ? tr("stopped within %1 s + %2 s").arg(n("deceleration"), n("margin"))
                   : tr("stopped within the deceleration time + %1 s").arg(n("margin"));
    case T::Read: {
        const QString name = s.value(QStringLiteral("parameter")).toString();
        if (name.isEmpty())
            return tr("no value chosen to read yet");
        const ParameterMeta* meta = profile ? profile->parameter(name) : nullptr;
        const QString label = meta && !meta->label.isEmpty() ? meta->label : name;
        if (s.contains(QStringLiteral("equals")))
            return tr("%1 is \"%2\"").arg(label, s.value(QStringLiteral("equals")).toString());
        return tr("%1 between %2 and %3")
            .arg(label, s.contains(QStringLiteral("lower")) ? n("lower") : tr("any"),
                 withUnit(s.contains(QStringLiteral("upper")) ? n("upper") : tr("any")));
    }
    }
    return QString();
}

QString RecipeStepKinds::line(const QJsonObject& step, const Profile* profile)
{
    const Kind* kind = of(step.value(QStringLiteral("type")).toString());
    if (!kind)
        return step.value(QStringLiteral("type")).toString();
    const QString detail = summary(step, profile);
    return detail.isEmpty() ? title(kind->type) : tr("%1: %2").arg(title(kind->type), detail);
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
