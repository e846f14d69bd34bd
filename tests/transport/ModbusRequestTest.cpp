#include "transport/ModbusRequest.h"
#include "transport/ModbusBackend.h"
#include "transport/ModbusResult.h"
#include "transport/RtuFrame.h"

#include <gtest/gtest.h>

using namespace opentop;

TEST(ModbusRequestTest, PduBytes)
{
    EXPECT_EQ(ModbusRequest::readHolding(1, 0xCA03, 1).pdu(),
              RtuFrame::fromHex(QStringLiteral("03 CA 03 00 01")));
    EXPECT_EQ(ModbusRequest::writeMultiple(1, 0x0403, {0, 100}).pdu(),
              RtuFrame::fromHex(QStringLiteral("10 04 03 00 02 04 00 00 00 64")));
    EXPECT_EQ(ModbusRequest::rawRequest(1, 0x41, QByteArray("\x01\x02", 2)).pdu(),
              RtuFrame::fromHex(QStringLiteral("41 01 02")));
    const ModbusRequest id = ModbusRequest::readDeviceIdentification(1, 2, 3);
    EXPECT_TRUE(id.raw);
    EXPECT_EQ(id.pdu(), RtuFrame::fromHex(QStringLiteral("2B 0E 02 03")));
}

TEST(ModbusRequestTest, ValidateAcceptsGoodRequests)
{
    EXPECT_EQ(ModbusRequest::readHolding(1, 0, 1).validate(), QString());
    EXPECT_EQ(ModbusRequest::readInput(247, 0xFF83, 125).validate(), QString());
    EXPECT_EQ(ModbusRequest::writeSingle(0, 0x2000, 1).validate(), QString()); // broadcast write
    EXPECT_EQ(ModbusRequest::writeMultiple(0, 0, QVector<quint16>(123, 1)).validate(), QString());
    EXPECT_EQ(ModbusRequest::readDeviceIdentification(1).validate(), QString());
}

// DBU manual 11-3: only functions 06h and 10h may be broadcast; anything else sent to machine
// number 0 is refused before it reaches the line, with a reason.
TEST(ModbusRequestTest, OnlyWritesMayBeBroadcast)
{
    EXPECT_EQ(ModbusRequest::writeSingle(0, 0x2003, 0).validate(), QString());
    EXPECT_EQ(ModbusRequest::writeMultiple(0, 0x0403, {0, 100}).validate(), QString());
    EXPECT_EQ(ModbusRequest::rawRequest(0, 0x06, QByteArray::fromHex("20030000")).validate(),
              QString());
    const struct
    {
        ModbusRequest request;
        const char* function;
    } refused[] = {
        {ModbusRequest::readHolding(0, 0x2003, 1), "0x03"},
        {ModbusRequest::readInput(0, 0x0065, 2), "0x04"},
        {ModbusRequest::readDeviceIdentification(0), "0x2B"},
        {ModbusRequest::rawRequest(0, 0x05, QByteArray::fromHex("0000FF00")), "0x05"},
        {ModbusRequest::rawRequest(0, 0x0F, QByteArray::fromHex("00000001010001")), "0x0F"},
        {ModbusRequest::rawRequest(0, 0x41, QByteArray()), "0x41"},
    };
    for (const auto& r : refused) {
        const QString error = r.request.validate();
        EXPECT_TRUE(error.contains(
            QStringLiteral("Function %1 cannot be broadcast").arg(QString::fromLatin1(r.function))))
            << qPrintable(error);
        EXPECT_TRUE(error.contains(QStringLiteral("only functions 06h and 10h")))
            << qPrintable(error);
        // The same request to one drive is fine.
        ModbusRequest unicast = r.request;
        unicast.slave = 1;
        EXPECT_EQ(unicast.validate(), QString()) << r.function;
    }
}

TEST(ModbusRequestTest, ValidateRejectsWithReasons)
{
    EXPECT_TRUE(ModbusRequest::readHolding(1, 0, 0).validate().contains(QStringLiteral("1–125")));
    EXPECT_FALSE(ModbusRequest::readHolding(1, 0, 126).validate().isEmpty());
    EXPECT_TRUE(
        ModbusRequest::readHolding(0, 0, 1).validate().contains(QStringLiteral("broadcast")));
    EXPECT_TRUE(ModbusRequest::readHolding(248, 0, 1).validate().contains(QStringLiteral("1–247")));
    EXPECT_FALSE(ModbusRequest::readHolding(1, 0xFFFF, 2).validate().isEmpty()); // past 0xFFFF
    EXPECT_FALSE(ModbusRequest::writeMultiple(1, 0, QVector<quint16>(124, 1)).validate().isEmpty());
    EXPECT_FALSE(ModbusRequest::writeMultiple(1, 0, {}).validate().isEmpty());
    ModbusRequest mismatch = ModbusRequest::writeMultiple(1, 0, {1, 2});
    mismatch.count = 3;
    EXPECT_FALSE(mismatch.validate().isEmpty());
    ModbusRequest noValue = ModbusRequest::writeSingle(1, 0, 1);
    noValue.values.clear();
    EXPECT_FALSE(noValue.validate().isEmpty());
    EXPECT_FALSE(ModbusRequest::readDeviceIdentification(0).validate().isEmpty());
    ModbusRequest unknown = ModbusRequest::readHolding(1, 0, 1);
    unknown.function = 0x41; // not raw: nothing knows how to encode it
    EXPECT_FALSE(unknown.validate().isEmpty());
    ModbusRequest timeout = ModbusRequest::readHolding(1, 0, 1);
    timeout.timeoutMs = 5;
    EXPECT_TRUE(timeout.validate().contains(QStringLiteral("10–10000")));
    ModbusRequest retries = ModbusRequest::readHolding(1, 0, 1);
    retries.retries = 11;
    EXPECT_FALSE(retries.validate().isEmpty());
    EXPECT_FALSE(ModbusRequest::rawRequest(1, 0x41, QByteArray(253, 0)).validate().isEmpty());
}

TEST(ModbusRequestTest, Describe)
{
    EXPECT_EQ(ModbusRequest::readInput(1, 0x0109, 1).describe(),
              QStringLiteral("read 04 0x0109 ×1"));
    EXPECT_EQ(ModbusRequest::writeSingle(1, 3, 1).describe(),
              QStringLiteral("write 06 0x0003 = 1"));
    EXPECT_EQ(ModbusRequest::writeMultiple(0, 0x0403, {0, 100}).describe(),
              QStringLiteral("broadcast write 10 0x0403 ×2 = 0, 100"));
}

TEST(ModbusResultTest, ErrorTextsAndReplySummaries)
{
    ModbusResult r;
    r.error = ModbusError::Timeout;
    r.attempts = 3;
    EXPECT_EQ(r.errorText(), QStringLiteral("timeout after 3 attempts"));
    r.error = ModbusError::PortError;
    r.message = QStringLiteral("read failed: Input/output error");
    EXPECT_TRUE(r.errorText().contains(QStringLiteral("Input/output error")));
    EXPECT_EQ(modbusExceptionName(0x0B), QStringLiteral("Gateway target device failed to respond"));
    EXPECT_EQ(modbusExceptionName(0xFF), QStringLiteral("Undefined error"));

    ModbusResult ok;
    ok.error = ModbusError::Ok;
    ok.registers = {1500};
    EXPECT_EQ(ModbusBackend::describeReply(ModbusRequest::readInput(1, 0x0109, 1), ok),
              QStringLiteral("→ 1500"));
    ok.registers = {1};
    EXPECT_EQ(ModbusBackend::describeReply(ModbusRequest::writeSingle(1, 3, 1), ok),
              QStringLiteral("echo 0x0003 = 1"));
    ModbusResult ex;
    ex.error = ModbusError::Exception;
    ex.exceptionCode = 2;
    EXPECT_EQ(ModbusBackend::describeReply(ModbusRequest::readInput(1, 0x0109, 1), ex),
              QStringLiteral("exception 02 Illegal data address"));
}
