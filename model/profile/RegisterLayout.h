#pragma once

#include "model/profile/ParameterMeta.h"

#include <QByteArray>
#include <QString>
#include <QVector>

namespace opentop {

// How a parameter's raw value lies in its registers: 16 or 32 bits, signed or not, a float's
// bits, the word order of two registers (and a bit field a drive keeps in the other word), and
// text as two characters a register. No checking here: ValueCodec validates against the profile.
class RegisterLayout
{
public:
    // Registers -> raw value (0 for text).
    static double registersToRaw(const ParameterMeta& meta, const QVector<quint16>& registers);
    // Raw value -> registers, rounded and cut to the register's bits (zeros for text).
    static QVector<quint16> rawToRegisters(const ParameterMeta& meta, double raw);
    // A 2-register bit field whose fields all lie in one word that reads 0, while the other
    // word has bits only where the fields are: the drive keeps the word in the other register.
    static bool wordsSwapped(const ParameterMeta& meta, quint32 wide);
    // The bits the parameter's fields occupy.
    static quint32 fieldMask(const ParameterMeta& meta);
    // Text registers: two Latin-1 characters each, high byte first, up to the first NUL, trimmed.
    static QString registersToText(const QVector<quint16>& registers);
    // `latin1` padded with NULs to `capacity` bytes (an even number), two bytes a register.
    static QVector<quint16> textToRegisters(QByteArray latin1, int capacity);
};

} // namespace opentop
