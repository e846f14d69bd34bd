// libFuzzer harness: the RTU reply decoder. The first byte picks the request the reply answers
// (read holding/input, write single/multiple, 0x2B device identification); the rest is the
// reply as received. Framing (expectedReplyLength) and decoding (decodeReply) must never read
// past the bytes given, whatever the length, CRC, exception or object list says.
#include "transport/ModbusRequest.h"
#include "transport/ModbusResult.h"
#include "transport/RtuFrame.h"
#include <QByteArray>
#include <cstddef>
#include <cstdint>

using opentop::ModbusRequest;

static ModbusRequest requestFor(uint8_t selector)
{
    const quint8 slave = static_cast<quint8>(1 + (selector >> 3) % 3);
    switch (selector & 7) {
    case 0:
        return ModbusRequest::readHolding(slave, 0x1000, 17);
    case 1:
        return ModbusRequest::readInput(slave, 0x0100, 2);
    case 2:
        return ModbusRequest::writeSingle(slave, 0x100D, 2);
    case 3:
        return ModbusRequest::writeMultiple(slave, 0x1001, {1, 2, 3});
    case 4:
        return ModbusRequest::readDeviceIdentification(slave, 1, 0);
    case 5:
        return ModbusRequest::readDeviceIdentification(slave, 4, 2);
    case 6:
        return ModbusRequest::readHolding(slave, 0, 125);
    default:
        return ModbusRequest::readHolding(slave, 0x1013, 1);
    }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size < 1)
        return 0;
    const ModbusRequest request = requestFor(data[0]);
    const QByteArray reply(reinterpret_cast<const char*>(data + 1),
                           static_cast<qsizetype>(size - 1));
    // framing as the backend does it, byte by byte
    for (qsizetype n = 0; n <= reply.size(); ++n)
        (void)opentop::RtuFrame::expectedReplyLength(request, reply.left(n));
    opentop::ModbusResult result;
    opentop::RtuFrame::decodeReply(request, reply, &result);
    // the server side reads requests from the same kind of bytes
    (void)opentop::RtuFrame::expectedRequestLength(reply);
    ModbusRequest parsed;
    (void)opentop::RtuFrame::decodeRequest(reply, &parsed);
    return 0;
}
