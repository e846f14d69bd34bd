#include "model/profile/ParameterMeta.h"

#include "model/profile/ValueContext.h"

#include <algorithm>
#include <cmath>

namespace opentop {

bool ValueSpec::isRecommended(double raw) const
{
    if (recommended.isEmpty())
        return true;
    const double eps = 1e-9 * std::max(1.0, std::fabs(raw)); // f32 values read back
    return std::any_of(recommended.begin(), recommended.end(), [raw, eps](const ValueRange& r) {
        return raw >= r.min - eps && raw <= r.max + eps;
    });
}

bool ParameterMeta::dependsOnParameter() const
{
    for (const ValueCondition& c : conditions) {
        if (!c.param.isEmpty())
            return true;
    }
    return false;
}

QStringList ParameterMeta::controllingParameters() const
{
    QStringList names;
    for (const ValueCondition& c : conditions) {
        if (!c.param.isEmpty() && !names.contains(c.param))
            names << c.param;
    }
    return names;
}

const ValueSpec& ParameterMeta::specFor(const ValueContext& context, QString* unresolved) const
{
    if (unresolved)
        unresolved->clear();
    for (const ValueCondition& c : conditions) {
        if (!c.variant.isEmpty()) {
            if (c.variant == context.variant)
                return c.spec;
            continue;
        }
        const std::optional<qint64> controlling = context.rawOf(c.param);
        if (!controlling) {
            // Without the controlling value no case can be chosen; the caller must refuse to
            // encode rather than guess (the codes of an I/O function depend on the mode).
            if (unresolved)
                *unresolved = c.param;
            return spec;
        }
        if (*controlling == c.equals)
            return c.spec;
    }
    return spec;
}

QString ParameterMeta::addressText() const
{
    return QStringLiteral("0x") +
           QStringLiteral("%1").arg(address, 4, 16, QLatin1Char('0')).toUpper();
}

QString ParameterMeta::functionsText() const
{
    auto fc = [](quint8 f) {
        return QStringLiteral("%1").arg(f, 2, 16, QLatin1Char('0')).toUpper();
    };
    if (readFunction && writeFunction)
        return fc(readFunction) + QLatin1Char('/') + fc(writeFunction);
    if (readFunction)
        return fc(readFunction);
    if (writeFunction)
        return fc(writeFunction);
    return QStringLiteral("--");
}

QString dataTypeName(DataType type)
{
    switch (type) {
    case DataType::U16:
        return QStringLiteral("u16");
    case DataType::S16:
        return QStringLiteral("s16");
    case DataType::U32:
        return QStringLiteral("u32");
    case DataType::S32:
        return QStringLiteral("s32");
    case DataType::F32:
        return QStringLiteral("f32");
    case DataType::String:
        return QStringLiteral("string");
    case DataType::Bits:
        return QStringLiteral("bits");
    }
    return QString();
}

std::optional<DataType> dataTypeFromName(const QString& name)
{
    for (DataType t : {DataType::U16, DataType::S16, DataType::U32, DataType::S32, DataType::F32,
                       DataType::String, DataType::Bits}) {
        if (dataTypeName(t) == name)
            return t;
    }
    return std::nullopt;
}

QString accessName(Access access)
{
    switch (access) {
    case Access::ReadOnly:
        return QStringLiteral("ro");
    case Access::ReadWrite:
        return QStringLiteral("rw");
    case Access::WriteOnly:
        return QStringLiteral("wo");
    }
    return QString();
}

} // namespace opentop
