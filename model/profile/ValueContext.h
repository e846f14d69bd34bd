#pragma once

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

namespace opentop {

// What a value's allowed set may depend on: the drive variant and other parameters' raw values.
struct ValueContext
{
    QString variant; // empty when not known
    // With the variant unknown: every variant the device could be. A value must then suit all
    // of them (e.g. 300–3000 r/min for a DBU that may be a DBU400).
    QStringList possibleVariants;
    std::function<std::optional<qint64>(const QString& parameter)> parameterRaw;
    // How messages name a parameter: the program's windows use the profile's label, the command
    // line (where names are typed) the internal name, which is also what is used when unset.
    std::function<QString(const QString& parameter)> displayName;

    std::optional<qint64> rawOf(const QString& parameter) const
    {
        return parameterRaw ? parameterRaw(parameter) : std::nullopt;
    }
    QString nameFor(const QString& parameter) const
    {
        const QString shown = displayName ? displayName(parameter) : QString();
        return shown.isEmpty() ? parameter : shown;
    }
};

} // namespace opentop
