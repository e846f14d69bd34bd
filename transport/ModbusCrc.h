#pragma once

#include <QByteArray>
#include <cstddef>
#include <cstdint>

namespace opentop {

// CRC-16/MODBUS (poly 0xA001 reflected, init 0xFFFF); transmitted low byte first.
class ModbusCrc
{
public:
    static quint16 compute(const uint8_t* data, std::size_t length);
    static quint16 compute(const QByteArray& data);
    // Appends the CRC (low byte first) to an ADU without one.
    static QByteArray append(const QByteArray& aduWithoutCrc);
    // True when the last two bytes are the CRC of the rest.
    static bool check(const QByteArray& adu);
};

} // namespace opentop
