#include "model/profile/ValueCodec.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <limits>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ValueCodec", text);
}

// Integer bounds of the wire type, in raw units.
std::pair<double, double> typeBounds(DataType type)
{
    switch (type) {
    case DataType::U16:
        return {0, 65535};
    case DataType::S16:
        return {-32768, 32767};
    case DataType::U32:
        return {0, 4294967295.0};
    case DataType::S32:
        return {-2147483648.0, 2147483647.0};
    case DataType::Bits:
        return {0, 4294967295.0};
    case DataType::F32:
        return {-std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
    case DataType::String:
        return {0, 0};
    }
    return {0, 0};
}

bool isInteger(DataType type)
{
    return type != DataType::F32 && type != DataType::String;
}

QString normalizedLabel(QString text)
{
    text = text.trimmed().toLower();
    text.remove(QRegularExpression(QStringLiteral("[\\s_\\-/().]")));
    return text;
}

} // namespace

QString ValueCodec::recommendationWarning(const ParameterMeta& meta, double raw,
                                          const ValueContext& context)
{
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    if (!unresolved.isEmpty() || spec.isRecommended(raw))
        return QString();
    const QString shown = formatNumber(raw * spec.scale, spec.decimals) +
                          (spec.unit.isEmpty() ? QString() : QLatin1Char(' ') + spec.unit);
    return tr("%1: %2 is outside the recommended range %3; it is allowed and will be written")
        .arg(context.nameFor(meta.name), shown, recommendedText(meta, context));
}

QString ValueCodec::checkRaw(const ParameterMeta& meta, double raw, const ValueContext& context)
{
    if (context.variant.isEmpty() && !context.possibleVariants.isEmpty()) {
        const bool variantDependent =
            std::any_of(meta.conditions.begin(), meta.conditions.end(),
                        [](const ValueCondition& c) { return !c.variant.isEmpty(); });
        if (variantDependent) {
            for (const QString& v : context.possibleVariants) {
                ValueContext one = context;
                one.variant = v;
                one.possibleVariants.clear();
                const QString error = checkRaw(meta, raw, one);
                if (!error.isEmpty())
                    return error + tr(" (the variant is not known, so the value must suit %1; name "
                                      "the variant to use its own range)")
                                       .arg(context.possibleVariants.join(QStringLiteral(", ")));
            }
            return QString();
        }
    }
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    if (!unresolved.isEmpty())
        return tr("%1: the allowed values depend on %2, which has not been read")
            .arg(context.nameFor(meta.name), context.nameFor(unresolved));
    const auto [lo, hi] = typeBounds(meta.type);
    if (!std::isfinite(raw) || raw < lo || raw > hi ||
        (isInteger(meta.type) && raw != std::floor(raw)))
        return tr("%1: value out of the register's range; allowed: %2")
            .arg(context.nameFor(meta.name), allowedText(meta, context));
    if (spec.ranges.isEmpty() && spec.options.isEmpty())
        return QString();
    if (ValueFormat::findOption(spec, raw))
        return QString();
    const double eps = meta.type == DataType::F32 ? 1e-9 * std::max(1.0, std::fabs(raw)) : 0.0;
    for (const ValueRange& r : spec.ranges) {
        if (raw >= r.min - eps && raw <= r.max + eps)
            return QString();
    }
    const QString shown = formatNumber(raw * spec.scale, spec.decimals);
    return tr("%1: %2 is not allowed; allowed: %3")
        .arg(context.nameFor(meta.name),
             shown + (spec.unit.isEmpty() ? QString() : QLatin1Char(' ') + spec.unit),
             allowedText(meta, context));
}

ParamValue ValueCodec::decode(const ParameterMeta& meta, const QVector<quint16>& registers,
                              const ValueContext& context)
{
    ParamValue v;
    v.registers = registers;
    if (registers.size() != meta.registerCount) {
        v.error = tr("%1: expected %2 registers, got %3")
                      .arg(context.nameFor(meta.name))
                      .arg(meta.registerCount)
                      .arg(registers.size());
        return v;
    }
    v.valid = true;
    if (meta.type == DataType::String) {
        v.text = RegisterLayout::registersToText(registers);
        return v;
    }
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    v.raw = registersToRaw(meta, registers);
    v.number = v.raw * spec.scale;
    // The English label: the value as files, recipes and scripts name it; format() shows it.
    if (const EnumOption* o = ValueFormat::findOption(spec, v.raw))
        v.text = o->canonicalLabel.isEmpty() ? o->label : o->canonicalLabel;
    if (unresolved.isEmpty() && meta.kind != QLatin1String("command")) {
        v.error = checkRaw(meta, v.raw, context);
        v.allowed = v.error.isEmpty();
    }
    return v;
}

ValueCodec::Encoded ValueCodec::encodeNumber(const ParameterMeta& meta, double value,
                                             const ValueContext& context)
{
    Encoded e;
    if (meta.type == DataType::String) {
        e.error = tr("%1 is text, not a number").arg(context.nameFor(meta.name));
        return e;
    }
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    if (!unresolved.isEmpty()) {
        e.error = checkRaw(meta, 0, context);
        return e;
    }
    double raw = value / spec.scale;
    if (isInteger(meta.type)) {
        const double rounded = std::round(raw);
        if (std::fabs(raw - rounded) > 1e-6 * std::max(1.0, std::fabs(raw))) {
            e.error = tr("%1: %2 is finer than the step of %3 %4; allowed: %5")
                          .arg(context.nameFor(meta.name), QString::number(value),
                               formatNumber(spec.scale, spec.decimals), spec.unit,
                               allowedText(meta, context));
            return e;
        }
        raw = rounded;
    }
    return encodeRaw(meta, raw, context);
}

ValueCodec::Encoded ValueCodec::encodeRaw(const ParameterMeta& meta, double raw,
                                          const ValueContext& context)
{
    Encoded e;
    e.error = checkRaw(meta, raw, context);
    e.ok = e.error.isEmpty();
    e.raw = raw;
    if (e.ok) {
        e.registers = rawToRegisters(meta, raw);
        e.warning = recommendationWarning(meta, raw, context);
    }
    return e;
}

ValueCodec::Encoded ValueCodec::encodeText(const ParameterMeta& meta, const QString& input,
                                           const ValueContext& context)
{
    Encoded e;
    const QString text = input.trimmed();
    if (meta.type == DataType::String) {
        const int capacity = meta.registerCount * 2;
        if (text.size() > capacity) {
            e.error = tr("%1: at most %2 characters").arg(context.nameFor(meta.name)).arg(capacity);
            return e;
        }
        for (QChar c : text) {
            if (c.unicode() < 0x20 || c.unicode() > 0x7E) {
                e.error = tr("%1: only printable ASCII characters are allowed")
                              .arg(context.nameFor(meta.name));
                return e;
            }
        }
        e.registers = RegisterLayout::textToRegisters(text.toLatin1(), capacity);
        e.ok = true;
        return e;
    }
    if (text.isEmpty()) {
        e.error = tr("%1: no value given; allowed: %2")
                      .arg(context.nameFor(meta.name), allowedText(meta, context));
        return e;
    }
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    if (!unresolved.isEmpty()) {
        e.error = checkRaw(meta, 0, context);
        return e;
    }
    // An enumeration label first: "CCW", "cw/stop", "Disabled". The profile's English label
    // (what scripts and files use) before the label in the profile language.
    const QString wanted = normalizedLabel(text);
    for (const EnumOption& o : spec.options) {
        if (normalizedLabel(o.canonicalLabel) == wanted)
            return encodeRaw(meta, double(o.value), context);
    }
    for (const EnumOption& o : spec.options) {
        if (normalizedLabel(o.label) == wanted)
            return encodeRaw(meta, double(o.value), context);
    }
    // The start of exactly one label: "communication" for "Communication priority".
    const EnumOption* prefixMatch = nullptr;
    int prefixMatches = 0;
    for (const EnumOption& o : spec.options) {
        if (!wanted.isEmpty() && !wanted.front().isDigit() &&
            (normalizedLabel(o.label).startsWith(wanted) ||
             normalizedLabel(o.canonicalLabel).startsWith(wanted))) {
            prefixMatch = &o;
            ++prefixMatches;
        }
    }
    if (prefixMatches == 1)
        return encodeRaw(meta, double(prefixMatch->value), context);
    // A label that exists in another case: say when it is available (a Mode1 function on a
    // drive in Mode2).
    for (const ValueCondition& c : meta.conditions) {
        for (const EnumOption& o : c.spec.options) {
            if (!c.param.isEmpty() && (normalizedLabel(o.label) == wanted ||
                                       normalizedLabel(o.canonicalLabel) == wanted)) {
                e.error = tr("%1: \"%2\" is only available when %3 is %4; allowed now: %5")
                              .arg(context.nameFor(meta.name), text, context.nameFor(c.param))
                              .arg(c.equals)
                              .arg(allowedText(meta, context));
                return e;
            }
        }
    }
    // A hexadecimal code is a raw value ("0x0011"), for enumerations and bit fields.
    if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
        bool ok = false;
        const qulonglong raw = text.mid(2).toULongLong(&ok, 16);
        if (!ok || !isInteger(meta.type)) {
            e.error = tr("%1: \"%2\" is not a valid value; allowed: %3")
                          .arg(context.nameFor(meta.name), text, allowedText(meta, context));
            return e;
        }
        return encodeRaw(meta, double(raw), context);
    }
    // A number, optionally followed by the unit ("2.5 s", "1500 r/min", "1500rpm").
    // The unit in the profile language or the profile's own ("30 일" or "30 d").
    QString number = text;
    const QString unit = spec.canonicalUnit;
    if (!spec.unit.isEmpty() && number.endsWith(spec.unit, Qt::CaseInsensitive))
        number.chop(spec.unit.size());
    else if (!unit.isEmpty() && number.endsWith(unit, Qt::CaseInsensitive))
        number.chop(unit.size());
    else if (unit == QLatin1String("r/min") &&
             number.endsWith(QLatin1String("rpm"), Qt::CaseInsensitive))
        number.chop(3);
    bool ok = false;
    const double value = number.trimmed().toDouble(&ok);
    if (!ok) {
        e.error = tr("%1: \"%2\" is not a valid value; allowed: %3")
                      .arg(context.nameFor(meta.name), text, allowedText(meta, context));
        return e;
    }
    // Enumeration codes are raw values; everything else is in engineering units.
    if (spec.ranges.isEmpty() && !spec.options.isEmpty())
        return encodeRaw(meta, value, context);
    return encodeNumber(meta, value, context);
}

} // namespace opentop
