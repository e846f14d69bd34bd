// The serial line's RS-485 and low-latency options: parsed into the settings, wrong values
// named with the allowed ones, and refused for a bus that has no serial line.
#include "connection/ConnectionOptions.h"
#include "cli/ExitCode.h"
#include "tests/cli/CliTestSupport.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

std::optional<ConnectionSettings> parse(const QString& line, QString* error)
{
    QCommandLineParser parser;
    ConnectionOptions::addTo(parser);
    const QStringList args =
        QStringList{QStringLiteral("opentop")} + line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    EXPECT_TRUE(parser.parse(args)) << qPrintable(parser.errorText());
    return ConnectionOptions::fromParser(parser, QString(), error);
}

} // namespace

TEST(ConnectionOptionsTest, SerialLineOptionsReachTheSettings)
{
    QString error;
    auto s = parse(QStringLiteral("--port /dev/ttyS1"), &error);
    ASSERT_TRUE(s) << qPrintable(error);
    EXPECT_EQ(s->rs485, ConnectionSettings::Rs485::Off);
    EXPECT_TRUE(s->rtsHighWhileSending);
    EXPECT_EQ(s->rtsDelayUs, 0);
    EXPECT_TRUE(s->lowLatency);

    s = parse(QStringLiteral("--port /dev/ttyS1 --rs485 kernel --rts-polarity low --rts-delay "
                             "1500 --low-latency off"),
              &error);
    ASSERT_TRUE(s) << qPrintable(error);
    EXPECT_EQ(s->rs485, ConnectionSettings::Rs485::Kernel);
    EXPECT_FALSE(s->rtsHighWhileSending);
    EXPECT_EQ(s->rtsDelayUs, 1500);
    EXPECT_FALSE(s->lowLatency);

    for (const char* mode : {"off", "auto", "kernel", "rts", "RTS"}) {
        s = parse(QStringLiteral("--port /dev/ttyS1 --rs485 %1").arg(QLatin1String(mode)), &error);
        ASSERT_TRUE(s) << mode << qPrintable(error);
        EXPECT_EQ(ConnectionSettings::rs485Name(s->rs485), QString::fromLatin1(mode).toLower());
    }
    EXPECT_TRUE(ConnectionOptions::names().contains(QStringLiteral("low-latency")));
}

TEST(ConnectionOptionsTest, WrongValuesNameTheAllowedOnes)
{
    const struct
    {
        const char* option;
        const char* named;
    } cases[] = {
        {"--rs485 on", "use off (the adapter switches direction itself), auto, kernel or rts"},
        {"--rts-polarity up", "use high or low"},
        {"--rts-delay -1", "use 0–100000 µs"},
        {"--rts-delay 100001", "use 0–100000 µs"},
        {"--rts-delay 1ms", "use 0–100000 µs"},
        {"--low-latency yes", "use on or off"},
    };
    for (const auto& c : cases) {
        QString error;
        const QString line = QStringLiteral("--port /dev/ttyS1 ") + QLatin1String(c.option);
        EXPECT_FALSE(parse(line, &error)) << c.option;
        EXPECT_TRUE(error.contains(QString::fromUtf8(c.named))) << qPrintable(error);
        // The command line says so before anything is opened (exit 2), in every program.
        const CliRun r = runCli((line + QStringLiteral(" scan")).split(QLatin1Char(' ')));
        EXPECT_EQ(r.code, ExitUsage) << qPrintable(r.err);
        EXPECT_TRUE(r.err.contains(QString::fromUtf8(c.named))) << qPrintable(r.err);
        EXPECT_FALSE(r.err.contains(QStringLiteral("Cannot open"))) << qPrintable(r.err);
    }
}

TEST(ConnectionOptionsTest, RefusedForABusWithoutASerialLine)
{
    QString error;
    EXPECT_FALSE(parse(QStringLiteral("--sim dbu200@1 --rs485 kernel"), &error));
    EXPECT_EQ(error, QStringLiteral("--rs485 applies to a serial port (--port), not to a "
                                    "simulated bus"));
    EXPECT_FALSE(parse(QStringLiteral("--tcp 10.0.0.5 --low-latency off"), &error));
    EXPECT_EQ(error, QStringLiteral("--low-latency applies to a serial port (--port), not to a "
                                    "Modbus TCP gateway (--tcp)"));

    // The GUI's fallback bus is no excuse either: the option asks for a port.
    QCommandLineParser parser;
    ConnectionOptions::addTo(parser);
    ASSERT_TRUE(parser.parse(
        {QStringLiteral("opentop"), QStringLiteral("--rts-delay"), QStringLiteral("500")}));
    EXPECT_TRUE(ConnectionOptions::hasSerialLineOptions(parser));
    EXPECT_FALSE(ConnectionOptions::fromParser(parser, QStringLiteral("dbu200@1"), &error));
    EXPECT_EQ(error, QStringLiteral(
                         "--rts-delay applies to a serial port only: give it with --port PATH"));

    const CliRun r =
        runCli({QStringLiteral("--sim"), QStringLiteral("dbu200@1"),
                QStringLiteral("--rts-polarity"), QStringLiteral("low"), QStringLiteral("scan")});
    EXPECT_EQ(r.code, ExitUsage) << qPrintable(r.out + r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--rts-polarity applies to a serial port")))
        << qPrintable(r.err);
    EXPECT_FALSE(r.out.contains(QStringLiteral("found"))) << qPrintable(r.out);
}
