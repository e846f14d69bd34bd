#include "model/profile/ValueFormat.h"

#include <QCoreApplication>
#include <QStringList>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ValueFormat", text);
}

} // namespace

QString ValueFormat::formatNumber(double number, int decimals)
{
    QString text = QString::number(number, 'f', decimals);
    if (text.startsWith(QLatin1Char('-')) && text.toDouble() == 0.0)
        text.remove(0, 1); // no "-0.0"
    return text;
}

const EnumOption* ValueFormat::findOption(const ValueSpec& spec, double raw)
{
    for (const EnumOption& o : spec.options) {
        if (static_cast<double>(o.value) == raw)
            return &o;
    }
    return nullptr;
}

QString ValueFormat::rangesText(const QVector<ValueRange>& intervals, const ValueSpec& spec)
{
    QStringList ranges;
    for (const ValueRange& r : intervals) {
        const QString lo = formatNumber(r.min * spec.scale, spec.decimals);
        const QString hi = formatNumber(r.max * spec.scale, spec.decimals);
        ranges << (r.min == r.max ? lo : lo + QStringLiteral("–") + hi);
    }
    if (ranges.isEmpty())
        return QString();
    const QString last = ranges.takeLast();
    QString text = ranges.isEmpty() ? last : ranges.join(QStringLiteral(", ")) + tr(" or ") + last;
    if (!spec.unit.isEmpty())
        text += QLatin1Char(' ') + spec.unit;
    return text;
}

QString ValueFormat::recommendedText(const ParameterMeta& meta, const ValueContext& context)
{
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    if (!unresolved.isEmpty())
        return QString();
    return rangesText(spec.recommended, spec);
}

QString ValueFormat::allowedText(const ParameterMeta& meta, const ValueContext& context)
{
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    if (!unresolved.isEmpty())
        return tr("depends on %1, which is not known yet").arg(context.nameFor(unresolved));
    if (meta.type == DataType::String)
        return tr("text of up to %1 characters").arg(meta.registerCount * 2);
    QString text = rangesText(spec.ranges, spec);
    QStringList options;
    for (const EnumOption& o : spec.options)
        options << QStringLiteral("%1 (%2)").arg(o.label).arg(o.value);
    if (!options.isEmpty())
        text += (text.isEmpty() ? QString() : tr(", or ")) + options.join(QStringLiteral(", "));
    return text.isEmpty() ? tr("any value") : text;
}

QString ValueFormat::format(const ParameterMeta& meta, const ParamValue& value,
                            const ValueContext& context, bool canonical)
{
    if (!value.valid)
        return tr("(invalid)");
    if (meta.type == DataType::String)
        return value.text;
    if (meta.type == DataType::Bits) {
        const int digits = meta.registerCount * 4;
        return QStringLiteral("0x%1").arg(qulonglong(value.raw), digits, 16, QLatin1Char('0'));
    }
    const ValueSpec& spec = meta.specFor(context);
    if (const EnumOption* o = findOption(spec, value.raw))
        return canonical && !o->canonicalLabel.isEmpty() ? o->canonicalLabel : o->label;
    if (spec.ranges.isEmpty() && !spec.options.isEmpty())
        return tr("unknown code %1").arg(qlonglong(value.raw));
    const QString number = formatNumber(value.number, spec.decimals);
    // A spec made in code rather than read from a profile has no canonical unit.
    const QString& unit =
        canonical && !spec.canonicalUnit.isEmpty() ? spec.canonicalUnit : spec.unit;
    return unit.isEmpty() ? number : number + QLatin1Char(' ') + unit;
}

} // namespace opentop
