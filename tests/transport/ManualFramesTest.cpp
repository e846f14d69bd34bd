// Every example frame of the DBU manual (000_306a808c77939fd6.txt) chapters 9, 11 and 12,
// byte for byte, in both directions: the project's encoder must produce the manual's query, the
// decoder must give the manual's meaning for the reply, and the simulator side must parse the
// query and produce the reply.
//
// The CRCs were recomputed independently (CRC-16/MODBUS, python3). One example is wrong in the
// manual: chapter 9 "select SPno3", 01 06 20 0F 00 02 33 CB, whose CRC is 33 C8 (C8 33 little
// endian is 0xC833). The tests use the correct bytes and check that the manual's are refused.
#include "transport/ModbusCrc.h"
#include "transport/ModbusRequest.h"
#include "transport/ModbusResult.h"
#include "transport/RtuFrame.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

namespace opentop {
namespace {

QByteArray bytes(std::initializer_list<int> list)
{
    QByteArray b;
    for (int x : list)
        b.append(char(x));
    return b;
}

// Independent of RtuFrame::toHex, for messages and comparisons.
std::string hex(const QByteArray& b)
{
    std::string s;
    char buf[4];
    for (int i = 0; i < b.size(); ++i) {
        std::snprintf(buf, sizeof buf, i ? " %02X" : "%02X", unsigned(quint8(b[i])));
        s += buf;
    }
    return s;
}

std::string errorName(ModbusError error)
{
    return modbusErrorName(error).toStdString();
}

ModbusResult decode(const ModbusRequest& request, const QByteArray& reply)
{
    ModbusResult result;
    RtuFrame::decodeReply(request, reply, &result);
    return result;
}

// A 06 example: query and echo reply are the same 8 bytes.
void checkWriteSingle(quint8 slave, quint16 address, quint16 value, const QByteArray& frame)
{
    const ModbusRequest request = ModbusRequest::writeSingle(slave, address, value);
    EXPECT_TRUE(request.validate().isEmpty()) << request.validate().toStdString();
    EXPECT_EQ(hex(RtuFrame::encodeRequest(request)), hex(frame));
    EXPECT_EQ(hex(request.pdu()), hex(frame.mid(1, frame.size() - 3)));

    EXPECT_EQ(RtuFrame::expectedReplyLength(request, frame), 8);
    const ModbusResult result = decode(request, frame);
    EXPECT_EQ(errorName(result.error), errorName(ModbusError::Ok)) << result.message.toStdString();
    EXPECT_EQ(result.registers, QVector<quint16>{value});

    // Simulator side: parse the query, answer with the manual's reply.
    EXPECT_EQ(RtuFrame::expectedRequestLength(frame), 8);
    ModbusRequest parsed;
    ASSERT_TRUE(RtuFrame::decodeRequest(frame, &parsed));
    EXPECT_EQ(int(parsed.slave), int(slave));
    EXPECT_EQ(int(parsed.function), 0x06);
    EXPECT_EQ(parsed.address, address);
    EXPECT_EQ(parsed.values, QVector<quint16>{value});
    EXPECT_EQ(hex(RtuFrame::encodeWriteSingleReply(slave, address, value)), hex(frame));
}

// A 03/04 example reading one register.
void checkReadOne(const ModbusRequest& request, const QByteArray& query, const QByteArray& reply,
                  quint16 value)
{
    EXPECT_TRUE(request.validate().isEmpty()) << request.validate().toStdString();
    EXPECT_EQ(hex(RtuFrame::encodeRequest(request)), hex(query));

    EXPECT_EQ(RtuFrame::expectedReplyLength(request, reply.left(3)), 7);
    const ModbusResult result = decode(request, reply);
    EXPECT_EQ(errorName(result.error), errorName(ModbusError::Ok)) << result.message.toStdString();
    EXPECT_EQ(result.registers, QVector<quint16>{value});

    EXPECT_EQ(RtuFrame::expectedRequestLength(query), 8);
    ModbusRequest parsed;
    ASSERT_TRUE(RtuFrame::decodeRequest(query, &parsed));
    EXPECT_EQ(int(parsed.slave), int(request.slave));
    EXPECT_EQ(int(parsed.function), int(request.function));
    EXPECT_EQ(parsed.address, request.address);
    EXPECT_EQ(parsed.count, 1);
    EXPECT_EQ(hex(RtuFrame::encodeReadReply(request.slave, request.function, {value})), hex(reply));
}

// 9-2: select running data SPno1 on machine 01: write 0000h to 0x200F.
TEST(ManualFrames, Chapter9SelectSpno1)
{
    checkWriteSingle(0x01, 0x200F, 0x0000, bytes({0x01, 0x06, 0x20, 0x0F, 0x00, 0x00, 0xB2, 0x09}));
}

// 9-2: select running data SPno3 (0002h). ERRATUM: the manual prints the CRC as 33 CB (query,
// reply and table); CRC-16/MODBUS of 01 06 20 0F 00 02 is 0xC833, sent 33 C8.
TEST(ManualFrames, Chapter9SelectSpno3WithCorrectedCrc)
{
    const QByteArray correct = bytes({0x01, 0x06, 0x20, 0x0F, 0x00, 0x02, 0x33, 0xC8});
    const QByteArray printed = bytes({0x01, 0x06, 0x20, 0x0F, 0x00, 0x02, 0x33, 0xCB});
    checkWriteSingle(0x01, 0x200F, 0x0002, correct);

    const ModbusRequest request = ModbusRequest::writeSingle(0x01, 0x200F, 0x0002);
    EXPECT_NE(hex(RtuFrame::encodeRequest(request)), hex(printed));
    // A device answering with the manual's bytes would be answering with a CRC error.
    EXPECT_EQ(errorName(decode(request, printed).error), errorName(ModbusError::CrcError));
}

// 11-5: writing the read-only communication error register 0x007B with 06 is answered with
// function 86h and exception code 02h (illegal data address).
TEST(ManualFrames, Chapter11ExceptionReply)
{
    const QByteArray query = bytes({0x01, 0x06, 0x00, 0x7B, 0x00, 0x0A, 0x79, 0xD4});
    const QByteArray reply = bytes({0x01, 0x86, 0x02, 0xC3, 0xA1});
    const ModbusRequest request = ModbusRequest::writeSingle(0x01, 0x007B, 0x000A);
    EXPECT_EQ(hex(RtuFrame::encodeRequest(request)), hex(query));

    EXPECT_EQ(RtuFrame::expectedReplyLength(request, reply.left(3)), 5);
    const ModbusResult result = decode(request, reply);
    EXPECT_EQ(errorName(result.error), errorName(ModbusError::Exception));
    EXPECT_EQ(int(result.exceptionCode), 0x02);
    EXPECT_TRUE(modbusExceptionName(0x02).contains(QStringLiteral("address"), Qt::CaseInsensitive))
        << modbusExceptionName(0x02).toStdString();

    ModbusRequest parsed;
    ASSERT_TRUE(RtuFrame::decodeRequest(query, &parsed));
    EXPECT_EQ(parsed.address, 0x007B);
    EXPECT_EQ(parsed.values, QVector<quint16>{0x000A});
    EXPECT_EQ(hex(RtuFrame::encodeException(0x01, 0x06, 0x02)), hex(reply));
}

// 12-1 function 03: read SPno2's speed 0xCA03; 03 E8 = 1000 r/min.
TEST(ManualFrames, Chapter12ReadHolding)
{
    const QByteArray query = bytes({0x01, 0x03, 0xCA, 0x03, 0x00, 0x01, 0x4B, 0xD2});
    checkReadOne(ModbusRequest::readHolding(0x01, 0xCA03, 1), query,
                 bytes({0x01, 0x03, 0x02, 0x03, 0xE8, 0xB8, 0xFA}), 1000);
    // The manual's own notation, and the log format of the header comment.
    EXPECT_EQ(hex(RtuFrame::fromHex(QStringLiteral("01h 03h CA 03h 00 01h 4B D2h"))), hex(query));
    EXPECT_EQ(RtuFrame::toHex(query), QStringLiteral("01 03 CA 03 00 01 4B D2"));
}

// 12-1 function 04: read alarm record 1 at 0x1C01; 00 0B = alarm code 0Bh (Hall sensor error).
TEST(ManualFrames, Chapter12ReadInput)
{
    checkReadOne(ModbusRequest::readInput(0x01, 0x1C01, 1),
                 bytes({0x01, 0x04, 0x1C, 0x01, 0x00, 0x01, 0x67, 0x9A}),
                 bytes({0x01, 0x04, 0x02, 0x00, 0x0B, 0xF8, 0xF7}), 0x000B);
}

// 12-1 function 06: communication connection command, 0001h to 0x0003, echoed.
TEST(ManualFrames, Chapter12WriteSingle)
{
    checkWriteSingle(0x01, 0x0003, 0x0001, bytes({0x01, 0x06, 0x00, 0x03, 0x00, 0x01, 0xB8, 0x0A}));
}

// 12-1 function 10: speed reduction 1.00 -> 100 = 00000064h, high word first, at 0x0403.
TEST(ManualFrames, Chapter12WriteMultiple)
{
    const QByteArray query =
        bytes({0x01, 0x10, 0x04, 0x03, 0x00, 0x02, 0x04, 0x00, 0x00, 0x00, 0x64, 0x80, 0x91});
    const QByteArray reply = bytes({0x01, 0x10, 0x04, 0x03, 0x00, 0x02, 0xB0, 0xF8});
    const ModbusRequest request = ModbusRequest::writeMultiple(0x01, 0x0403, {0x0000, 0x0064});
    EXPECT_TRUE(request.validate().isEmpty()) << request.validate().toStdString();
    EXPECT_EQ(request.count, 2);
    EXPECT_EQ(hex(RtuFrame::encodeRequest(request)), hex(query));

    EXPECT_EQ(RtuFrame::expectedReplyLength(request, reply), 8);
    const ModbusResult result = decode(request, reply);
    EXPECT_EQ(errorName(result.error), errorName(ModbusError::Ok)) << result.message.toStdString();

    EXPECT_EQ(RtuFrame::expectedRequestLength(query), 13);
    ModbusRequest parsed;
    ASSERT_TRUE(RtuFrame::decodeRequest(query, &parsed));
    EXPECT_EQ(int(parsed.function), 0x10);
    EXPECT_EQ(parsed.address, 0x0403);
    EXPECT_EQ(parsed.count, 2);
    EXPECT_EQ(parsed.values, (QVector<quint16>{0x0000, 0x0064}));
    EXPECT_EQ(hex(RtuFrame::encodeWriteMultipleReply(0x01, 0x0403, 2)), hex(reply));
}

// Every frame of chapters 9, 11 and 12 with its CRC as printed (low byte first), corrected where
// the manual is wrong.
struct CrcExample
{
    const char* where;
    QByteArray frame;
    quint16 crc;
};

std::vector<CrcExample> crcExamples()
{
    return {
        {"9-2 SPno1 query/reply", bytes({0x01, 0x06, 0x20, 0x0F, 0x00, 0x00, 0xB2, 0x09}), 0x09B2},
        {"9-2 SPno3 query/reply (corrected)",
         bytes({0x01, 0x06, 0x20, 0x0F, 0x00, 0x02, 0x33, 0xC8}), 0xC833},
        {"11-5 query", bytes({0x01, 0x06, 0x00, 0x7B, 0x00, 0x0A, 0x79, 0xD4}), 0xD479},
        {"11-5 exception reply", bytes({0x01, 0x86, 0x02, 0xC3, 0xA1}), 0xA1C3},
        {"12-1 03 query", bytes({0x01, 0x03, 0xCA, 0x03, 0x00, 0x01, 0x4B, 0xD2}), 0xD24B},
        {"12-1 03 reply", bytes({0x01, 0x03, 0x02, 0x03, 0xE8, 0xB8, 0xFA}), 0xFAB8},
        {"12-1 04 query", bytes({0x01, 0x04, 0x1C, 0x01, 0x00, 0x01, 0x67, 0x9A}), 0x9A67},
        {"12-1 04 reply", bytes({0x01, 0x04, 0x02, 0x00, 0x0B, 0xF8, 0xF7}), 0xF7F8},
        {"12-1 06 query/reply", bytes({0x01, 0x06, 0x00, 0x03, 0x00, 0x01, 0xB8, 0x0A}), 0x0AB8},
        {"12-1 10 query",
         bytes({0x01, 0x10, 0x04, 0x03, 0x00, 0x02, 0x04, 0x00, 0x00, 0x00, 0x64, 0x80, 0x91}),
         0x9180},
        {"12-1 10 reply", bytes({0x01, 0x10, 0x04, 0x03, 0x00, 0x02, 0xB0, 0xF8}), 0xF8B0},
    };
}

TEST(ManualFrameCrc, EveryManualFrameChecks)
{
    for (const CrcExample& e : crcExamples()) {
        SCOPED_TRACE(e.where);
        const QByteArray body = e.frame.left(e.frame.size() - 2);
        EXPECT_TRUE(ModbusCrc::check(e.frame)) << hex(e.frame);
        EXPECT_EQ(ModbusCrc::compute(body), e.crc);
        EXPECT_EQ(ModbusCrc::compute(reinterpret_cast<const uint8_t*>(body.constData()),
                                     std::size_t(body.size())),
                  e.crc);
        EXPECT_EQ(hex(ModbusCrc::append(body)), hex(e.frame));

        // One flipped bit anywhere, data or CRC, must be caught.
        for (int i = 0; i < e.frame.size(); ++i) {
            QByteArray damaged = e.frame;
            damaged[i] = char(damaged[i] ^ 0x01);
            EXPECT_FALSE(ModbusCrc::check(damaged)) << "byte " << i << ": " << hex(damaged);
        }
    }
}

TEST(ManualFrameCrc, ManualErratumSpno3IsRefused)
{
    // As printed in chapter 9 (query, reply and table): CRC 33 CB, which is wrong.
    EXPECT_FALSE(ModbusCrc::check(bytes({0x01, 0x06, 0x20, 0x0F, 0x00, 0x02, 0x33, 0xCB})));
    EXPECT_NE(ModbusCrc::compute(bytes({0x01, 0x06, 0x20, 0x0F, 0x00, 0x02})), 0xCB33);
}

} // namespace
} // namespace opentop
