#pragma once

#include "model/profile/ValueContext.h"

#include <QString>
#include <QVector>
#include <optional>

namespace opentop {

class DeviceParameters;

// A drive's values as they will be once its pending edits are written: the edit where there is
// one, the device value otherwise. Previews and allowed ranges that depend on another setting
// use it, so that they follow what the user is about to write rather than the drive's state.
class PendingValues
{
public:
    // Registers of the edit, else of the device value; empty when neither is known.
    static QVector<quint16> registers(const DeviceParameters* parameters, const QString& name);
    // Engineering value (enumeration codes as numbers); nothing when not known.
    static std::optional<double> number(const DeviceParameters* parameters, const QString& name);
    // The session's context with pending edits in place of the device values.
    static ValueContext context(const DeviceParameters* parameters);
};

} // namespace opentop
