#pragma once

#include <QString>
#include <QVector>

namespace opentop {

// A decoded value in all the forms callers need.
struct ParamValue
{
    bool valid = false; // false when the registers could not be decoded
    QVector<quint16> registers;
    double raw = 0;    // integer types: the integer; f32: the float
    double number = 0; // engineering value (raw * scale)
    // Strings: the text; enumerations: the profile's English label (EnumOption::canonicalLabel),
    // an interface like the raw value. For people: ValueCodec::format.
    QString text;
    QString error;       // why not valid, or why outside the allowed set
    bool allowed = true; // false when the device holds a value the profile does not allow
};

} // namespace opentop
