#include "connection/ConnectionOptions.h"

#include "sim/SimBus.h"

#include "model/bus/BusSpec.h"
#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>

namespace opentop {

namespace {
QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ConnectionOptions", text);
}

const QStringList kSerialLineOptions = {QStringLiteral("rs485"), QStringLiteral("rts-polarity"),
                                        QStringLiteral("rts-delay"), QStringLiteral("low-latency")};

} // namespace

QString ConnectionOptions::readSerialLine(const QCommandLineParser& parser, ConnectionSettings* s)
{
    auto value = [&](const char* name) {
        return parser.value(QString::fromLatin1(name)).trimmed().toLower();
    };
    if (parser.isSet(QStringLiteral("rs485")) &&
        !ConnectionSettings::rs485FromName(value("rs485"), &s->rs485))
        return tr("--rs485 %1: use off (the adapter switches direction itself), auto, kernel "
                  "or rts")
            .arg(parser.value(QStringLiteral("rs485")));
    if (parser.isSet(QStringLiteral("rts-polarity"))) {
        const QString polarity = value("rts-polarity");
        if (polarity != QLatin1String("high") && polarity != QLatin1String("low"))
            return tr("--rts-polarity %1: use high or low (the RTS level while sending)")
                .arg(parser.value(QStringLiteral("rts-polarity")));
        s->rtsHighWhileSending = polarity == QLatin1String("high");
    }
    if (parser.isSet(QStringLiteral("rts-delay"))) {
        bool ok = false;
        s->rtsDelayUs = value("rts-delay").toInt(&ok);
        if (!ok || s->rtsDelayUs < 0 || s->rtsDelayUs > ConnectionSettings::kMaxRtsDelayUs)
            return tr("--rts-delay %1: use 0–%2 µs (0: the driver's or libmodbus' own delay)")
                .arg(parser.value(QStringLiteral("rts-delay")))
                .arg(ConnectionSettings::kMaxRtsDelayUs);
    }
    if (parser.isSet(QStringLiteral("low-latency"))) {
        const QString on = value("low-latency");
        if (on != QLatin1String("on") && on != QLatin1String("off"))
            return tr("--low-latency %1: use on or off")
                .arg(parser.value(QStringLiteral("low-latency")));
        s->lowLatency = on == QLatin1String("on");
    }
    if (s->kind == ConnectionSettings::Kind::Serial)
        return QString();
    for (const QString& name : kSerialLineOptions) {
        if (!parser.isSet(name))
            continue;
        if (parser.isSet(QStringLiteral("tcp")))
            return tr("--%1 applies to a serial port (--port), not to a Modbus TCP gateway "
                      "(--tcp)")
                .arg(name);
        if (parser.isSet(QStringLiteral("sim")))
            return tr("--%1 applies to a serial port (--port), not to a simulated bus").arg(name);
        return tr("--%1 applies to a serial port only: give it with --port PATH").arg(name);
    }
    return QString();
}

void ConnectionOptions::addTo(QCommandLineParser& parser)
{
    parser.addOptions({
        {QStringLiteral("port"), tr("Serial device (e.g. /dev/ttyUSB0 or a pty path)."),
         tr("PATH")},
        {QStringLiteral("tcp"), tr("Modbus TCP gateway, HOST:PORT (port defaults to 502)."),
         tr("HOST:PORT")},
        {QStringLiteral("sim"), tr("In-process simulated bus, e.g. dbu200@1,dbu400@150,dcpid@7."),
         tr("SPEC")},
        {QStringLiteral("family"),
         tr("Device family whose serial defaults apply (dbu: 19200 8N1, dcpid: 9600 8E1)."),
         tr("FAMILY")},
        {QStringLiteral("baud"), tr("Baud rate, 1200–115200."), tr("BAUD")},
        {QStringLiteral("parity"), tr("Parity: N, E or O."), tr("N|E|O")},
        {QStringLiteral("stop-bits"), tr("Stop bits: 1 or 2."), tr("N")},
        {QStringLiteral("drive-format"),
         tr("Drives that talk another line format than the port's, switched to between "
            "transactions: ID=[BAUD:]FORMAT,... e.g. 7=9600:8E1 or 7=8N2 (BAUD defaults to the "
            "port's). A DBU works only at 8N1; a DC controller at 8E1, 8O1 or 8N2."),
         tr("LIST")},
        {QStringLiteral("timeout"),
         tr("Response timeout per attempt in ms, 10–10000 (default 200)."), tr("MS")},
        {QStringLiteral("retries"),
         tr("Extra attempts after no reply or a garbled one, 0–10 (default 3; 2 more while "
            "the line is noisy)."),
         tr("N")},
        {QStringLiteral("rs485"),
         tr("Who switches the RS-485 direction (serial port only): off (default: the adapter "
            "itself, as USB–RS-485 adapters do), kernel (the driver's RS-485 mode), rts (RTS "
            "from the program) or auto (kernel where the driver has it, else rts)."),
         tr("MODE")},
        {QStringLiteral("rts-polarity"),
         tr("RTS level while sending with --rs485 kernel, rts or auto: high (default) or low."),
         tr("high|low")},
        {QStringLiteral("rts-delay"),
         tr("RTS delay before and after sending in µs, 0–100000 (default 0: the driver's, or "
            "libmodbus' one character time; the kernel rounds up to whole ms)."),
         tr("US")},
        {QStringLiteral("low-latency"),
         tr("Ask the serial driver to pass received bytes on at once (USB adapters otherwise "
            "hold them up to 16 ms): on (default) or off."),
         tr("on|off")},
    });
}

bool ConnectionOptions::hasSerialLineOptions(const QCommandLineParser& parser)
{
    for (const QString& name : kSerialLineOptions)
        if (parser.isSet(name))
            return true;
    return false;
}

QStringList ConnectionOptions::names()
{
    return QStringList{QStringLiteral("port"),      QStringLiteral("tcp"),
                       QStringLiteral("sim"),       QStringLiteral("family"),
                       QStringLiteral("baud"),      QStringLiteral("parity"),
                       QStringLiteral("stop-bits"), QStringLiteral("timeout"),
                       QStringLiteral("retries"),   QStringLiteral("drive-format")} +
           kSerialLineOptions;
}

QString ConnectionOptions::valueError(const QCommandLineParser& parser)
{
    // With a stand-in bus, the only failures left are the values of the options given.
    QString error;
    if (fromParser(parser, QStringLiteral("dbu200@1"), &error))
        return QString();
    return error;
}

std::optional<ConnectionSettings> ConnectionOptions::fromParser(const QCommandLineParser& parser,
                                                                const QString& fallbackSim,
                                                                QString* error)
{
    auto fail = [&](const QString& message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    ConnectionSettings s;
    const int named = int(parser.isSet(QStringLiteral("port"))) +
                      int(parser.isSet(QStringLiteral("tcp"))) +
                      int(parser.isSet(QStringLiteral("sim")));
    if (named > 1)
        return fail(tr("give only one of --port, --tcp and --sim"));
    if (named == 0 && fallbackSim.isEmpty())
        return fail(tr("no bus given: use --port PATH, --tcp HOST:PORT or --sim SPEC"));

    // Serial defaults follow the device family (the DBU's 19200 8N1 unless told otherwise).
    const QString family = parser.isSet(QStringLiteral("family"))
                               ? parser.value(QStringLiteral("family"))
                               : QStringLiteral("dbu");
    const Profile* profile = ProfileRegistry::builtIn().family(family);
    if (!profile)
        return fail(
            tr("--family %1: unknown family; use one of %2")
                .arg(family, ProfileRegistry::builtIn().families().join(QStringLiteral(", "))));
    s.baud = profile->serial.baud;
    s.parity = profile->serial.parity;
    s.stopBits = profile->serial.stopBits;

    if (parser.isSet(QStringLiteral("port"))) {
        s.kind = ConnectionSettings::Kind::Serial;
        s.port = parser.value(QStringLiteral("port"));
    } else if (parser.isSet(QStringLiteral("tcp"))) {
        s.kind = ConnectionSettings::Kind::Tcp;
        const QString value = parser.value(QStringLiteral("tcp"));
        const int colon = value.lastIndexOf(QLatin1Char(':'));
        s.host = colon > 0 ? value.left(colon) : value;
        s.tcpPort = 502;
        if (colon > 0) {
            bool ok = false;
            s.tcpPort = value.mid(colon + 1).toInt(&ok);
            if (!ok)
                return fail(tr("--tcp: \"%1\" is not HOST:PORT").arg(value));
        }
    } else {
        s.kind = ConnectionSettings::Kind::Simulated;
        s.simSpec =
            parser.isSet(QStringLiteral("sim")) ? parser.value(QStringLiteral("sim")) : fallbackSim;
        QString specError;
        // The whole simulated bus is made once: drives' defects are checked against profiles.
        if (!SimBus::fromSpec(s.simSpec, &specError))
            return fail(tr("--sim: %1").arg(specError));
    }
    auto intOption = [&](const char* name, int* target) -> bool {
        const QString key = QString::fromLatin1(name);
        if (!parser.isSet(key))
            return true;
        bool ok = false;
        *target = parser.value(key).toInt(&ok);
        return ok;
    };
    // Every value given is checked whatever the connection's kind: a wrong option is a wrong
    // command line, never a communication failure.
    if (!intOption("baud", &s.baud) || s.baud < 1200 || s.baud > 115200)
        return fail(tr("--baud %1: use a baud rate 1200–115200 (e.g. 9600, 19200, 38400)")
                        .arg(parser.value(QStringLiteral("baud"))));
    if (!intOption("stop-bits", &s.stopBits) || (s.stopBits != 1 && s.stopBits != 2))
        return fail(
            tr("--stop-bits %1: use 1 or 2").arg(parser.value(QStringLiteral("stop-bits"))));
    if (!intOption("timeout", &s.timeoutMs) || s.timeoutMs < 10 || s.timeoutMs > 10000)
        return fail(tr("--timeout %1: use a response timeout of 10–10000 ms")
                        .arg(parser.value(QStringLiteral("timeout"))));
    if (!intOption("retries", &s.retries) || s.retries < 0 || s.retries > 10)
        return fail(tr("--retries %1: use 0–10 extra attempts")
                        .arg(parser.value(QStringLiteral("retries"))));
    if (parser.isSet(QStringLiteral("parity"))) {
        const QString p = parser.value(QStringLiteral("parity")).trimmed().toUpper();
        if (p != QLatin1String("N") && p != QLatin1String("E") && p != QLatin1String("O"))
            return fail(tr("--parity %1: use N (none), E (even) or O (odd)")
                            .arg(parser.value(QStringLiteral("parity"))));
        s.parity = p.at(0).toLatin1();
    }
    if (parser.isSet(QStringLiteral("drive-format"))) {
        if (s.kind == ConnectionSettings::Kind::Tcp)
            return fail(tr("--drive-format applies to a serial port (--port) or a simulated bus, "
                           "not to a Modbus TCP gateway (--tcp): the gateway sets its line "
                           "itself"));
        QString why;
        const auto table =
            LineFormat::parseTable(parser.value(QStringLiteral("drive-format")), s.baud, &why);
        if (!table)
            return fail(tr("--drive-format: %1").arg(why));
        s.driveLines = *table;
    }
    const QString line = readSerialLine(parser, &s);
    if (!line.isEmpty())
        return fail(line);
    const QString invalid = s.validate();
    if (!invalid.isEmpty())
        return fail(invalid);
    return s;
}

} // namespace opentop
