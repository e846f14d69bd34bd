#pragma once

#include <QString>
#include <functional>
#include <optional>

namespace opentop {

// What a value's allowed set may depend on: the drive variant and other parameters' raw values.
struct ValueContext
{
    QString variant; // empty when not known
    std::function<std::optional<qint64>(const QString& parameter)> parameterRaw;

    std::optional<qint64> rawOf(const QString& parameter) const
    {
        return parameterRaw ? parameterRaw(parameter) : std::nullopt;
    }
};

} // namespace opentop
