#include "model/profile/ValueCodec.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <cstring>
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

const EnumOption* findOption(const ValueSpec& spec, double raw)
{
    for (const EnumOption& o : spec.options) {
        if (static_cast<double>(o.value) == raw)
            return &o;
    }
    return nullptr;
}

// A 32-bit value as two registers in the parameter's word order.
QVector<quint16> words(const ParameterMeta& meta, quint32 v)
{
    const quint16 high = static_cast<quint16>(v >> 16);
    const quint16 low = static_cast<quint16>(v & 0xFFFF);
    if (meta.wordOrder == WordOrder::LowFirst)
        return {low, high};
    return {high, low};
}

} // namespace

quint32 ValueCodec::fieldMask(const ParameterMeta& meta)
{
    quint32 mask = 0;
    for (const BitField& b : meta.bits) {
        for (int i = b.bit; i < b.bit + b.width && i < 32; ++i)
            mask |= quint32(1) << i;
    }
    return mask;
}

bool ValueCodec::wordsSwapped(const ParameterMeta& meta, quint32 wide)
{
    if (meta.type != DataType::Bits || meta.registerCount != 2)
        return false;
    const quint32 mask = fieldMask(meta);
    const bool lowHalf = (mask & 0xFFFF0000u) == 0;
    const bool highHalf = (mask & 0x0000FFFFu) == 0;
    if (mask == 0 || (!lowHalf && !highHalf) || (wide & mask) != 0)
        return false;
    // Every field is in one word, which reads 0, and the other word holds bits only where the
    // fields are: the drive keeps the word in the other register.
    const quint32 moved = (wide >> 16) | (wide << 16);
    return moved != 0 && (moved & ~mask) == 0;
}

double ValueCodec::registersToRaw(const ParameterMeta& meta, const QVector<quint16>& regs)
{
    const bool lowFirst = meta.wordOrder == WordOrder::LowFirst;
    const quint32 wide = regs.size() >= 2 ? lowFirst ? (quint32(regs[1]) << 16) | regs[0]
                                                     : (quint32(regs[0]) << 16) | regs[1]
                                          : (regs.isEmpty() ? 0u : regs[0]);
    switch (meta.type) {
    case DataType::U16:
        return regs.isEmpty() ? 0 : regs[0];
    case DataType::S16:
        return regs.isEmpty() ? 0 : static_cast<qint16>(regs[0]);
    case DataType::U32:
        return wide;
    case DataType::S32:
        return static_cast<qint32>(wide);
    case DataType::Bits:
        if (meta.registerCount < 2)
            return regs.isEmpty() ? 0 : regs[0];
        return wordsSwapped(meta, wide) ? (wide >> 16) | (wide << 16) : wide;
    case DataType::F32: {
        float f;
        std::memcpy(&f, &wide, sizeof f);
        return f;
    }
    case DataType::String:
        return 0;
    }
    return 0;
}

QVector<quint16> ValueCodec::rawToRegisters(const ParameterMeta& meta, double raw)
{
    switch (meta.type) {
    case DataType::U16:
    case DataType::S16:
        return {static_cast<quint16>(static_cast<qint64>(std::llround(raw)) & 0xFFFF)};
    case DataType::Bits:
        if (meta.registerCount < 2)
            return {static_cast<quint16>(static_cast<qint64>(std::llround(raw)) & 0xFFFF)};
        [[fallthrough]];
    case DataType::U32:
    case DataType::S32: {
        const quint32 v = static_cast<quint32>(static_cast<qint64>(std::llround(raw)) & 0xFFFFFFFF);
        return words(meta, v);
    }
    case DataType::F32: {
        const float f = static_cast<float>(raw);
        quint32 v;
        std::memcpy(&v, &f, sizeof v);
        return words(meta, v);
    }
    case DataType::String:
        return QVector<quint16>(meta.registerCount, 0);
    }
    return {};
}

QString ValueCodec::formatNumber(double number, int decimals)
{
    QString text = QString::number(number, 'f', decimals);
    if (text.startsWith(QLatin1Char('-')) && text.toDouble() == 0.0)
        text.remove(0, 1); // no "-0.0"
    return text;
}

QString ValueCodec::recommendedText(const ParameterMeta& meta, const ValueContext& context)
{
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    if (!unresolved.isEmpty() || spec.recommended.isEmpty())
        return QString();
    QStringList ranges;
    for (const ValueRange& r : spec.recommended) {
        const QString lo = formatNumber(r.min * spec.scale, spec.decimals);
        const QString hi = formatNumber(r.max * spec.scale, spec.decimals);
        ranges << (r.min == r.max ? lo : lo + QStringLiteral("–") + hi);
    }
    const QString last = ranges.takeLast();
    QString text = ranges.isEmpty() ? last : ranges.join(QStringLiteral(", ")) + tr(" or ") + last;
    if (!spec.unit.isEmpty())
        text += QLatin1Char(' ') + spec.unit;
    return text;
}

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

QString ValueCodec::allowedText(const ParameterMeta& meta, const ValueContext& context)
{
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    if (!unresolved.isEmpty())
        return tr("depends on %1, which is not known yet").arg(context.nameFor(unresolved));
    if (meta.type == DataType::String)
        return tr("text of up to %1 characters").arg(meta.registerCount * 2);
    QStringList ranges;
    for (const ValueRange& r : spec.ranges) {
        const QString lo = formatNumber(r.min * spec.scale, spec.decimals);
        const QString hi = formatNumber(r.max * spec.scale, spec.decimals);
        ranges << (r.min == r.max ? lo : lo + QStringLiteral("–") + hi);
    }
    QString text;
    if (!ranges.isEmpty()) {
        const QString last = ranges.takeLast();
        text = ranges.isEmpty() ? last : ranges.join(QStringLiteral(", ")) + tr(" or ") + last;
        if (!spec.unit.isEmpty())
            text += QLatin1Char(' ') + spec.unit;
    }
    QStringList options;
    for (const EnumOption& o : spec.options)
        options << QStringLiteral("%1 (%2)").arg(o.label).arg(o.value);
    if (!options.isEmpty())
        text += (text.isEmpty() ? QString() : tr(", or ")) + options.join(QStringLiteral(", "));
    return text.isEmpty() ? tr("any value") : text;
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
    if (findOption(spec, raw))
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
        QByteArray bytes;
        for (quint16 r : registers) {
            bytes.append(char(r >> 8));
            bytes.append(char(r & 0xFF));
        }
        const int nul = bytes.indexOf('\0');
        if (nul >= 0)
            bytes.truncate(nul);
        v.text = QString::fromLatin1(bytes).trimmed();
        return v;
    }
    QString unresolved;
    const ValueSpec& spec = meta.specFor(context, &unresolved);
    v.raw = registersToRaw(meta, registers);
    v.number = v.raw * spec.scale;
    // The English label: the value as files, recipes and scripts name it; format() shows it.
    if (const EnumOption* o = findOption(spec, v.raw))
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
        QByteArray bytes = text.toLatin1();
        for (QChar c : text) {
            if (c.unicode() < 0x20 || c.unicode() > 0x7E) {
                e.error = tr("%1: only printable ASCII characters are allowed")
                              .arg(context.nameFor(meta.name));
                return e;
            }
        }
        bytes.append(QByteArray(capacity - bytes.size(), '\0'));
        for (int i = 0; i < capacity; i += 2)
            e.registers << quint16((quint8(bytes[i]) << 8) | quint8(bytes[i + 1]));
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

QString ValueCodec::format(const ParameterMeta& meta, const ParamValue& value,
                           const ValueContext& context)
{
    return formatAs(meta, value, context, false);
}

QString ValueCodec::formatCanonical(const ParameterMeta& meta, const ParamValue& value,
                                    const ValueContext& context)
{
    return formatAs(meta, value, context, true);
}

QString ValueCodec::formatAs(const ParameterMeta& meta, const ParamValue& value,
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
