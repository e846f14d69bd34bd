#include "transport/SerialPortList.h"

#include <QStringList>
#include <algorithm>
#include <gtest/gtest.h>

using namespace opentop;

TEST(ConnectionPortListTest, OneLineDescription)
{
    SerialPortList::Port p;
    p.systemLocation = QStringLiteral("/dev/ttyUSB0");
    p.description = QStringLiteral("FT232R USB UART");
    p.manufacturer = QStringLiteral("FTDI");
    p.serialNumber = QStringLiteral("A10K3XYZ");
    p.vendorId = 0x0403;
    p.productId = 0x6001;
    p.hasIds = true;
    EXPECT_EQ(p.oneLine(), QStringLiteral("/dev/ttyUSB0 — FT232R USB UART (FTDI, A10K3XYZ)"));
    EXPECT_EQ(p.vidPid(), QStringLiteral("0403:6001"));
    p.manufacturer.clear();
    p.serialNumber.clear();
    EXPECT_EQ(p.oneLine(), QStringLiteral("/dev/ttyUSB0 — FT232R USB UART (0403:6001)"));
    SerialPortList::Port bare;
    bare.systemLocation = QStringLiteral("/dev/ttyS0");
    EXPECT_EQ(bare.oneLine(), QStringLiteral("/dev/ttyS0"));
    EXPECT_EQ(bare.vidPid(), QString());
}

TEST(ConnectionPortListTest, ListingNeverShowsPtysAndHintSaysSo)
{
    for (const SerialPortList::Port& p : SerialPortList::available()) {
        EXPECT_FALSE(p.systemLocation.isEmpty());
        EXPECT_FALSE(p.systemLocation.startsWith(QStringLiteral("/dev/pts/")));
    }
    EXPECT_TRUE(SerialPortList::typedPathHint().contains(QStringLiteral("type")));
}

TEST(ConnectionPortListTest, PortsAreInTheOrderOfTheirNumbers)
{
    QStringList names{QStringLiteral("COM10"),         QStringLiteral("COM2"),
                      QStringLiteral("/dev/ttyUSB10"), QStringLiteral("/dev/ttyUSB2"),
                      QStringLiteral("/dev/ttyS0"),    QStringLiteral("COM1")};
    std::sort(names.begin(), names.end(), &SerialPortList::namedBefore);
    EXPECT_EQ(names, (QStringList{QStringLiteral("/dev/ttyS0"), QStringLiteral("/dev/ttyUSB2"),
                                  QStringLiteral("/dev/ttyUSB10"), QStringLiteral("COM1"),
                                  QStringLiteral("COM2"), QStringLiteral("COM10")}));
    EXPECT_FALSE(SerialPortList::namedBefore(QStringLiteral("COM3"), QStringLiteral("COM3")));
}
