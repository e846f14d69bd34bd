#include "transport/ConnectionSettings.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

ConnectionSettings serial()
{
    ConnectionSettings s;
    s.port = QStringLiteral("/dev/ttyUSB0");
    return s;
}

} // namespace

TEST(ConnectionSettingsTest, DefaultsAreValid)
{
    EXPECT_EQ(serial().validate(), QString());
    ConnectionSettings tcp;
    tcp.kind = ConnectionSettings::Kind::Tcp;
    EXPECT_EQ(tcp.validate(), QString());
}

TEST(ConnectionSettingsTest, MessagesNameAllowedValues)
{
    auto check = [](ConnectionSettings s, const char* allowed) {
        const QString message = s.validate();
        EXPECT_TRUE(message.contains(QString::fromUtf8(allowed))) << message.toStdString();
    };
    ConnectionSettings s = serial();
    s.port.clear();
    check(s, "/dev/ttyUSB0");
    s = serial();
    s.baud = 600;
    check(s, "1200–115200");
    s.baud = 230400;
    check(s, "1200–115200");
    s = serial();
    s.parity = 'M';
    check(s, "N (none), E (even) or O (odd)");
    s = serial();
    s.dataBits = 6;
    check(s, "7 or 8");
    s = serial();
    s.stopBits = 3;
    check(s, "1 or 2");
    s = serial();
    s.timeoutMs = 5;
    check(s, "10–10000 ms");
    s.timeoutMs = 10001;
    check(s, "10–10000 ms");
    s = serial();
    s.retries = 11;
    check(s, "0–10");
    ConnectionSettings tcp;
    tcp.kind = ConnectionSettings::Kind::Tcp;
    tcp.tcpPort = 0;
    check(tcp, "1–65535");
    tcp.tcpPort = 65536;
    check(tcp, "1–65535");
    // Edges are allowed.
    s = serial();
    s.baud = 1200;
    s.timeoutMs = 10;
    s.retries = 10;
    EXPECT_EQ(s.validate(), QString());
    s.baud = 115200;
    s.timeoutMs = 10000;
    s.retries = 0;
    s.stopBits = 2;
    s.dataBits = 7;
    s.parity = 'E';
    EXPECT_EQ(s.validate(), QString());
}

TEST(ConnectionSettingsTest, DescribeAndTiming)
{
    ConnectionSettings s = serial();
    EXPECT_EQ(s.describe(), QStringLiteral("/dev/ttyUSB0 19200 8N1"));
    EXPECT_NEAR(s.charTimeMs(), 10.0 / 19.2, 1e-9);
    s.parity = 'E';
    s.baud = 9600;
    EXPECT_NEAR(s.charTimeMs(), 11.0 / 9.6, 1e-9);
    EXPECT_GE(s.effectiveByteTimeoutMs(), 20);
    s.baud = 1200;
    EXPECT_GE(s.effectiveByteTimeoutMs(), int(4 * s.charTimeMs())); // scales with the baud rate
    s.byteTimeoutMs = 7;
    EXPECT_EQ(s.effectiveByteTimeoutMs(), 7);
    ConnectionSettings tcp;
    tcp.kind = ConnectionSettings::Kind::Tcp;
    tcp.host = QStringLiteral("10.0.0.5");
    EXPECT_EQ(tcp.describe(), QStringLiteral("tcp 10.0.0.5:502"));
}

TEST(ConnectionSettingsTest, SerialLineSettingsAreCheckedAndNamed)
{
    ConnectionSettings s = serial();
    EXPECT_EQ(s.rs485, ConnectionSettings::Rs485::Off);
    EXPECT_TRUE(s.rtsHighWhileSending);
    EXPECT_EQ(s.rtsDelayUs, 0);
    EXPECT_TRUE(s.lowLatency);
    s.rtsDelayUs = ConnectionSettings::kMaxRtsDelayUs;
    EXPECT_EQ(s.validate(), QString());
    s.rtsDelayUs = -1;
    EXPECT_TRUE(s.validate().contains(QStringLiteral("0–100000 µs"))) << qPrintable(s.validate());
    s.rtsDelayUs = 100001;
    EXPECT_TRUE(s.validate().contains(QStringLiteral("0–100000 µs"))) << qPrintable(s.validate());
    s = serial();
    s.rs485 = ConnectionSettings::Rs485(7); // e.g. from a damaged settings file
    EXPECT_TRUE(s.validate().contains(QStringLiteral("use off, auto, kernel or rts")))
        << qPrintable(s.validate());

    ConnectionSettings::Rs485 mode = ConnectionSettings::Rs485::Off;
    for (const char* name : {"off", "auto", "kernel", "rts"}) {
        ASSERT_TRUE(ConnectionSettings::rs485FromName(QString::fromLatin1(name), &mode)) << name;
        EXPECT_EQ(ConnectionSettings::rs485Name(mode), QString::fromLatin1(name));
    }
    EXPECT_TRUE(ConnectionSettings::rs485FromName(QStringLiteral(" Kernel "), &mode));
    EXPECT_EQ(mode, ConnectionSettings::Rs485::Kernel);
    EXPECT_FALSE(ConnectionSettings::rs485FromName(QStringLiteral("on"), &mode));
    EXPECT_EQ(mode, ConnectionSettings::Rs485::Kernel); // unchanged
}

TEST(ConnectionSettingsTest, DescribeNamesTheSerialLineSettingsOnlyWhenNotDefault)
{
    ConnectionSettings s = serial();
    EXPECT_EQ(s.describe(), QStringLiteral("/dev/ttyUSB0 19200 8N1"));
    s.rs485 = ConnectionSettings::Rs485::Kernel;
    EXPECT_EQ(s.describe(), QStringLiteral("/dev/ttyUSB0 19200 8N1 rs485=kernel"));
    s.rtsHighWhileSending = false;
    s.rtsDelayUs = 500;
    s.lowLatency = false;
    EXPECT_EQ(s.describe(), QStringLiteral("/dev/ttyUSB0 19200 8N1 rs485=kernel rts=low "
                                           "rts-delay=500us low-latency=off"));
    // Not part of a TCP or simulated connection.
    s.kind = ConnectionSettings::Kind::Tcp;
    EXPECT_EQ(s.describe(), QStringLiteral("tcp 127.0.0.1:502"));
}
