#pragma once

#include "model/profile/ParamValue.h"
#include "model/profile/ParameterMeta.h"
#include "model/profile/ValueContext.h"

#include <QString>

namespace opentop {

// A parameter's values and allowed values as text: numbers with the profile's decimals and
// unit, enumeration labels (in the profile language, or the profile's English ones for files),
// the allowed and the recommended ranges. ValueCodec's texts and messages are made of these.
class ValueFormat
{
public:
    // "2.5 s", "CCW", "1500 r/min", "-3 r/min"; `canonical`: the profile's English label and
    // unit (EnumOption::canonicalLabel, ValueSpec::canonicalUnit), whatever the profile language.
    static QString format(const ParameterMeta& meta, const ParamValue& value,
                          const ValueContext& context, bool canonical);
    // "0 or 250–3000 r/min", "CW (0), CCW (1)", "0.5 or 2.0–30.0 s".
    static QString allowedText(const ParameterMeta& meta, const ValueContext& context);
    // The recommended intervals as text ("0.0000–1.0000"); empty when there are none.
    static QString recommendedText(const ParameterMeta& meta, const ValueContext& context);
    // `decimals` after the point, never "-0.0".
    static QString formatNumber(double number, int decimals);
    // The enumeration option whose code is `raw`, or none.
    static const EnumOption* findOption(const ValueSpec& spec, double raw);

private:
    // "0 or 250–3000 r/min": the intervals in engineering units with the unit; empty for none.
    static QString rangesText(const QVector<ValueRange>& ranges, const ValueSpec& spec);
};

} // namespace opentop
