#pragma once

#include "model/profile/ParamValue.h"
#include "model/profile/ParameterMeta.h"
#include "model/profile/RegisterLayout.h"
#include "model/profile/ValueContext.h"
#include "model/profile/ValueFormat.h"

#include <QString>
#include <QVector>

namespace opentop {

// The one place where raw registers and engineering values are converted and validated. How
// values lie in registers is RegisterLayout's, how they read as text ValueFormat's.
class ValueCodec
{
public:
    struct Encoded
    {
        bool ok = false;
        QVector<quint16> registers;
        double raw = 0;
        QString error; // names the allowed values when a value is refused
        // An allowed value outside the profile's recommended range: written, but the caller
        // shows this (recommendationWarning). Empty otherwise.
        QString warning;
    };

    // Registers as read from the device -> value. Flags values outside the allowed set.
    static ParamValue decode(const ParameterMeta& meta, const QVector<quint16>& registers,
                             const ValueContext& context = {});
    // Engineering value (e.g. 2.5 for 2.5 s) -> registers, refusing anything not allowed.
    static Encoded encodeNumber(const ParameterMeta& meta, double value,
                                const ValueContext& context = {});
    // Text typed by a user: a number (optionally followed by the unit), an enumeration label or
    // code, or a string. "2.5", "2.5 s", "CCW", "1", "0x0001".
    static Encoded encodeText(const ParameterMeta& meta, const QString& text,
                              const ValueContext& context = {});
    // Raw value -> registers after checking it against the profile.
    static Encoded encodeRaw(const ParameterMeta& meta, double raw,
                             const ValueContext& context = {});
    // Raw value -> registers without validation (for the simulator and for raw service access).
    static QVector<quint16> rawToRegisters(const ParameterMeta& meta, double raw)
    {
        return RegisterLayout::rawToRegisters(meta, raw);
    }
    // A 2-register bit field register is read in its `wordOrder`, unless the drive shows that it
    // keeps the word in the other register: every field lies in one word, that word reads 0,
    // and the other word has bits only where the fields are (wordsSwapped). Then the words are
    // taken the other way round, so that a drive of either layout reads right.
    static double registersToRaw(const ParameterMeta& meta, const QVector<quint16>& registers)
    {
        return RegisterLayout::registersToRaw(meta, registers);
    }
    static bool wordsSwapped(const ParameterMeta& meta, quint32 wide)
    {
        return RegisterLayout::wordsSwapped(meta, wide);
    }
    // The bits the parameter's fields occupy.
    static quint32 fieldMask(const ParameterMeta& meta) { return RegisterLayout::fieldMask(meta); }
    // Empty when `raw` is allowed; otherwise a message naming the allowed values.
    static QString checkRaw(const ParameterMeta& meta, double raw,
                            const ValueContext& context = {});
    // The warning for an allowed value outside the recommended range ("recommended" in the
    // profile), naming that range: "pid.p: 2.5 is outside the recommended range 0.0000–1.0000;
    // it is allowed and will be written". Empty when `raw` is recommended or the parameter has no
    // recommendation. It does not check the allowed range (checkRaw does).
    static QString recommendationWarning(const ParameterMeta& meta, double raw,
                                         const ValueContext& context = {});
    // The recommended intervals as text ("0.0000–1.0000"); empty when there are none.
    static QString recommendedText(const ParameterMeta& meta, const ValueContext& context = {})
    {
        return ValueFormat::recommendedText(meta, context);
    }
    // "0 or 250–3000 r/min", "CW (0), CCW (1)", "0.5 or 2.0–30.0 s".
    static QString allowedText(const ParameterMeta& meta, const ValueContext& context = {})
    {
        return ValueFormat::allowedText(meta, context);
    }
    // "2.5 s", "CCW", "1500 r/min", "-3 r/min".
    static QString format(const ParameterMeta& meta, const ParamValue& value,
                          const ValueContext& context = {})
    {
        return ValueFormat::format(meta, value, context, false);
    }
    // The same with the profile's English label and unit (EnumOption::canonicalLabel,
    // ValueSpec::canonicalUnit), whatever the profile language: for files and --json.
    static QString formatCanonical(const ParameterMeta& meta, const ParamValue& value,
                                   const ValueContext& context = {})
    {
        return ValueFormat::format(meta, value, context, true);
    }
    static QString formatNumber(double number, int decimals)
    {
        return ValueFormat::formatNumber(number, decimals);
    }
};

} // namespace opentop
