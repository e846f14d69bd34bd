#include "model/profile/RegisterLayout.h"

#include <cmath>
#include <cstring>

namespace opentop {

namespace {

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

quint32 RegisterLayout::fieldMask(const ParameterMeta& meta)
{
    quint32 mask = 0;
    for (const BitField& b : meta.bits) {
        for (int i = b.bit; i < b.bit + b.width && i < 32; ++i)
            mask |= quint32(1) << i;
    }
    return mask;
}

bool RegisterLayout::wordsSwapped(const ParameterMeta& meta, quint32 wide)
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

double RegisterLayout::registersToRaw(const ParameterMeta& meta, const QVector<quint16>& regs)
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

QVector<quint16> RegisterLayout::rawToRegisters(const ParameterMeta& meta, double raw)
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

QString RegisterLayout::registersToText(const QVector<quint16>& registers)
{
    QByteArray bytes;
    for (quint16 r : registers) {
        bytes.append(char(r >> 8));
        bytes.append(char(r & 0xFF));
    }
    const int nul = bytes.indexOf('\0');
    if (nul >= 0)
        bytes.truncate(nul);
    return QString::fromLatin1(bytes).trimmed();
}

QVector<quint16> RegisterLayout::textToRegisters(QByteArray latin1, int capacity)
{
    latin1.append(QByteArray(capacity - latin1.size(), '\0'));
    QVector<quint16> registers;
    for (int i = 0; i < capacity; i += 2)
        registers << quint16((quint8(latin1[i]) << 8) | quint8(latin1[i + 1]));
    return registers;
}

} // namespace opentop
