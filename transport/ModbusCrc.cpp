#include "transport/ModbusCrc.h"

#include <array>

namespace opentop {

namespace {

// Table for the reflected polynomial 0xA001, built once at compile time.
constexpr std::array<quint16, 256> makeTable()
{
    std::array<quint16, 256> table{};
    for (int i = 0; i < 256; ++i) {
        quint16 crc = static_cast<quint16>(i);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 1) ? static_cast<quint16>((crc >> 1) ^ 0xA001)
                            : static_cast<quint16>(crc >> 1);
        table[static_cast<std::size_t>(i)] = crc;
    }
    return table;
}

constexpr std::array<quint16, 256> kTable = makeTable();

} // namespace

quint16 ModbusCrc::compute(const uint8_t* data, std::size_t length)
{
    quint16 crc = 0xFFFF;
    for (std::size_t i = 0; i < length; ++i)
        crc = static_cast<quint16>((crc >> 8) ^ kTable[(crc ^ data[i]) & 0xFF]);
    return crc;
}

quint16 ModbusCrc::compute(const QByteArray& data)
{
    return compute(reinterpret_cast<const uint8_t*>(data.constData()),
                   static_cast<std::size_t>(data.size()));
}

QByteArray ModbusCrc::append(const QByteArray& aduWithoutCrc)
{
    const quint16 crc = compute(aduWithoutCrc);
    QByteArray adu = aduWithoutCrc;
    adu.append(static_cast<char>(crc & 0xFF));
    adu.append(static_cast<char>(crc >> 8));
    return adu;
}

bool ModbusCrc::check(const QByteArray& adu)
{
    if (adu.size() < 3)
        return false;
    const auto* bytes = reinterpret_cast<const uint8_t*>(adu.constData());
    const std::size_t n = static_cast<std::size_t>(adu.size()) - 2;
    const quint16 received = static_cast<quint16>(bytes[n] | (bytes[n + 1] << 8));
    return compute(bytes, n) == received;
}

} // namespace opentop
