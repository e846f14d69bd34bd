#include "ConnectionOptions.h"

#include "bus/BusSpec.h"
#include "profile/ProfileRegistry.h"

#include <QCoreApplication>

namespace opentop {

namespace {
QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ConnectionOptions", text);
}
} // namespace

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
        {QStringLiteral("timeout"),
         tr("Response timeout per attempt in ms, 10–10000 (default 200)."), tr("MS")},
        {QStringLiteral("retries"),
         tr("Extra attempts after no reply or a garbled one, 0–10 (default 3; 2 more while "
            "the line is noisy)."),
         tr("N")},
    });
}

QStringList ConnectionOptions::names()
{
    return {QStringLiteral("port"),      QStringLiteral("tcp"),     QStringLiteral("sim"),
            QStringLiteral("family"),    QStringLiteral("baud"),    QStringLiteral("parity"),
            QStringLiteral("stop-bits"), QStringLiteral("timeout"), QStringLiteral("retries")};
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
            tr("unknown family \"%1\"; known: %2")
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
        if (!BusSpec::parse(s.simSpec, &specError))
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
    if (!intOption("baud", &s.baud))
        return fail(tr("--baud must be a number, 1200–115200"));
    if (!intOption("stop-bits", &s.stopBits))
        return fail(tr("--stop-bits must be 1 or 2"));
    if (!intOption("timeout", &s.timeoutMs))
        return fail(tr("--timeout must be a number of milliseconds, 10–10000"));
    if (!intOption("retries", &s.retries))
        return fail(tr("--retries must be a number, 0–10"));
    if (parser.isSet(QStringLiteral("parity"))) {
        const QString p = parser.value(QStringLiteral("parity")).toUpper();
        if (p != QLatin1String("N") && p != QLatin1String("E") && p != QLatin1String("O"))
            return fail(tr("--parity must be N, E or O"));
        s.parity = p.at(0).toLatin1();
    }
    const QString invalid = s.validate();
    if (!invalid.isEmpty())
        return fail(invalid);
    return s;
}

} // namespace opentop
