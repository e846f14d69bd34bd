#include "ConnectionSettings.h"

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
