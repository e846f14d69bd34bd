#include "transport/ModbusCrc.h"
#include "transport/RtuFrame.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

QByteArray hex(const char* text)
{
    return RtuFrame::fromHex(QString::fromLatin1(text));
}

} // namespace

TEST(CrcTest, StandardCheckValue)
{
    // CRC-16/MODBUS catalogue check value for "123456789".
    EXPECT_EQ(ModbusCrc::compute(QByteArray("123456789")), 0x4B37);
    EXPECT_EQ(ModbusCrc::compute(QByteArray()), 0xFFFF);
}

// Every example frame in the two manuals; all of them carry a correct CRC.
class CrcManualVectors : public ::testing::TestWithParam<const char*>
{
};

TEST_P(CrcManualVectors, ManualFrameChecksAndRebuilds)
{
    const QByteArray frame = hex(GetParam());
    ASSERT_GE(frame.size(), 4);
    EXPECT_TRUE(ModbusCrc::check(frame));
    EXPECT_EQ(ModbusCrc::append(frame.left(frame.size() - 2)), frame);
}

INSTANTIATE_TEST_SUITE_P(CrcTest, CrcManualVectors,
                         ::testing::Values("01 06 20 0F 00 00 B2 09", "01 03 CA 03 00 01 4B D2",
                                           "01 03 02 03 E8 B8 FA", "01 04 1C 01 00 01 67 9A",
                                           "01 04 02 00 0B F8 F7", "01 06 00 03 00 01 B8 0A",
                                           "01 10 04 03 00 02 04 00 00 00 64 80 91",
                                           "01 10 04 03 00 02 B0 F8", "01 06 00 7B 00 0A 79 D4",
                                           "01 86 02 C3 A1"));

TEST(CrcTest, LowByteFirstAndDetectsCorruption)
{
    const QByteArray adu = ModbusCrc::append(hex("01 03 CA 03 00 01"));
    EXPECT_EQ(quint8(adu.at(6)), 0x4B); // low byte first
    EXPECT_EQ(quint8(adu.at(7)), 0xD2);
    for (int i = 0; i < adu.size(); ++i) {
        QByteArray bad = adu;
        bad[i] = char(bad[i] ^ 0x01);
        EXPECT_FALSE(ModbusCrc::check(bad)) << "bit flip in byte " << i;
    }
    QByteArray swapped = adu;
    std::swap(swapped[6], swapped[7]);
    EXPECT_FALSE(ModbusCrc::check(swapped));
    EXPECT_FALSE(ModbusCrc::check(QByteArray("\x01\x02", 2)));
}
