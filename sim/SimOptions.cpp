#include "sim/SimOptions.h"

namespace opentop {

const QList<int>& SimOptions::bauds()
{
    static const QList<int> list = {1200,  2400,  4800,  9600,  14400,
                                    19200, 28800, 38400, 57600, 115200};
    return list;
}

QString SimOptions::usage()
{
    return tr(
        "Usage: opentop-sim --devices SPEC [options]\n"
        "Simulates Modbus RTU drives on a pseudo-terminal or as a Modbus TCP gateway.\n\n"
        "  --devices SPEC     devices and machine numbers, e.g. dbu200@1,dbu400@150,dcpid@7\n"
        "                     a drive's own line settings in braces, e.g.\n"
        "                     dcpid@7{format=8E1,baud=19200}: it hears only frames sent in\n"
        "                     that format (a pty passes the client's rate and parity on)\n"
        "  --pty [PATH]       serve on a pty (default); PATH: also create this symlink\n"
        "  --tcp HOST:PORT    serve Modbus TCP (HOST defaults to 127.0.0.1, PORT 0: any)\n"
        "  --baud N           line speed for wire timing and device settings (19200); a\n"
        "                     drive hears a frame only at its own rate and parity\n"
        "  --parity N|E|O     line parity (N): the drives without settings of their own\n"
        "                     are set to --baud and --parity\n"
        "  --wire-timing      delay replies as a real line at --baud would\n"
        "  --turnaround MS    device turnaround with --wire-timing (2)\n"
        "  --half-duplex      with --wire-timing: a request overlapping a reply on the line\n"
        "                     garbles both, one within 3.5 characters of a reply is lost\n"
        "  --faults LIST      e.g. drop=0.02,crc=0.01,late=0.01,busy=0.01,late_ms=1000\n"
        "  --seed N           seed of the fault injection (1)\n"
        "  --defect ID:LIST   defects of drive ID (repeatable), LIST of:\n"
        "                       firmware=MAJOR.MINOR  identification reports this version\n"
        "                       max_speed=N           the motor saturates at N (DBU r/min,\n"
        "                                             DC commutations/s), load high\n"
        "                       stall                 the motor does not turn, load high\n"
        "                       load=+N|-N|xF         load rate (DC: current %) off or scaled\n"
        "                       alarm=CODE@TIME       alarm after TIME running, e.g.\n"
        "                                             0x07@1500ms, overload@2s (DC: stall@1s)\n"
        "                       nostick=PARAM         writes acknowledged, old value stays\n"
        "                       nostore=PARAM         value lost at the next power cycle\n"
        "                     e.g. --defect 3:firmware=1.4 --defect 5:max_speed=800,load=+40\n"
        "  --motor LIST       the DC controllers' motor and load, e.g. inertia=2e-4,load=0.05;\n"
        "                     supply (V), resistance (ohm), no_load (1/s at full duty),\n"
        "                     commutations (per revolution), inertia (kg m2), viscous\n"
        "                     (N m s/rad), coulomb (N m), load (N m), gate (ms), tacho (V s)\n"
        "  --quiet            no frame trace on stderr\n"
        "  --lang CODE        language of messages: en, zh_TW, zh_CN, ko, ja\n"
        "  --help             this text\n"
        "  --version          the program's version\n\n"
        "Prints \"pty: PATH\" (and \"tcp: HOST:PORT\"), then \"ready\". Reads console commands\n"
        "from stdin (type help). Stops on SIGINT, SIGTERM or quit.\n");
}

std::optional<SimOptions> SimOptions::parse(const QStringList& arguments, QString* error)
{
    SimOptions o;
    auto failed = [error](const QString& message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    for (int i = 0; i < arguments.size(); ++i) {
        QString arg = arguments.at(i);
        QString inlineValue;
        bool hasInline = false;
        if (arg.startsWith(QLatin1String("--")) && arg.contains(QLatin1Char('='))) {
            inlineValue = arg.mid(arg.indexOf(QLatin1Char('=')) + 1);
            arg = arg.left(arg.indexOf(QLatin1Char('=')));
            hasInline = true;
        }
        // The value of an option that needs one.
        auto value = [&](QString* out) {
            if (hasInline) {
                *out = inlineValue;
                return true;
            }
            if (i + 1 >= arguments.size())
                return false;
            *out = arguments.at(++i);
            return true;
        };
        QString v;
        if (arg == QLatin1String("--help") || arg == QLatin1String("-h")) {
            o.help = true;
        } else if (arg == QLatin1String("--version")) {
            o.version = true;
        } else if (arg == QLatin1String("--lang")) {
            // Installed by main() before anything is printed (Language::requestedIn).
            if (!value(&v) || v.isEmpty())
                return failed(tr("--lang needs a language code such as ko"));
        } else if (arg == QLatin1String("--devices")) {
            if (!value(&o.devices) || o.devices.isEmpty())
                return failed(tr("--devices needs a device list such as dbu200@1,dcpid@7"));
        } else if (arg == QLatin1String("--pty")) {
            o.pty = true;
            if (hasInline)
                o.ptyLink = inlineValue;
            else if (i + 1 < arguments.size() && !arguments.at(i + 1).startsWith(QLatin1Char('-')))
                o.ptyLink = arguments.at(++i);
        } else if (arg == QLatin1String("--tcp")) {
            if (!value(&v))
                return failed(tr("--tcp needs HOST:PORT, e.g. 127.0.0.1:5020"));
            const int colon = v.lastIndexOf(QLatin1Char(':'));
            const QString host = colon >= 0 ? v.left(colon) : QString();
            bool ok = false;
            const int port = (colon >= 0 ? v.mid(colon + 1) : v).toInt(&ok);
            if (!ok || port < 0 || port > 65535)
                return failed(tr("--tcp needs HOST:PORT with PORT 0..65535, got '%1'").arg(v));
            o.tcp = true;
            if (!host.isEmpty())
                o.tcpHost = host;
            o.tcpPort = quint16(port);
        } else if (arg == QLatin1String("--baud")) {
            bool ok = false;
            const int baud = value(&v) ? v.toInt(&ok) : 0;
            if (!ok || !bauds().contains(baud)) {
                QStringList allowed;
                for (int b : bauds())
                    allowed << QString::number(b);
                return failed(tr("--baud must be one of %1, got '%2'")
                                  .arg(allowed.join(QStringLiteral(", ")), v));
            }
            o.baud = baud;
        } else if (arg == QLatin1String("--parity")) {
            const QString p = value(&v) ? v.toUpper() : QString();
            if (p != QLatin1String("N") && p != QLatin1String("E") && p != QLatin1String("O"))
                return failed(tr("--parity must be N, E or O, got '%1'").arg(v));
            o.parity = p.at(0).toLatin1();
        } else if (arg == QLatin1String("--wire-timing")) {
            o.wireTiming = true;
        } else if (arg == QLatin1String("--half-duplex")) {
            o.halfDuplex = true;
        } else if (arg == QLatin1String("--turnaround")) {
            bool ok = false;
            const double ms = value(&v) ? v.toDouble(&ok) : -1;
            if (!ok || ms < 0 || ms > 1000)
                return failed(tr("--turnaround must be 0..1000 ms, got '%1'").arg(v));
            o.turnaroundMs = ms;
        } else if (arg == QLatin1String("--faults")) {
            if (!value(&v))
                return failed(tr("--faults needs a list such as drop=0.02,crc=0.01"));
            QString why;
            const std::optional<FaultInjector::Rates> rates = FaultInjector::parse(v, &why);
            if (!rates)
                return failed(tr("--faults: %1").arg(why));
            o.faults = *rates;
        } else if (arg == QLatin1String("--seed")) {
            bool ok = false;
            const uint seed = value(&v) ? v.toUInt(&ok) : 0;
            if (!ok)
                return failed(tr("--seed must be a whole number 0..4294967295, got '%1'").arg(v));
            o.seed = seed;
        } else if (arg == QLatin1String("--defect")) {
            if (!value(&v))
                return failed(tr("--defect needs ID:DEFECT[,DEFECT...], e.g. 3:firmware=1.4; "
                                 "DEFECT: %1")
                                  .arg(SimDefectSpec::forms()));
            int slave = 0;
            QString why;
            const std::optional<SimDefectSpec> spec = SimDefectSpec::parseOption(v, &slave, &why);
            if (!spec)
                return failed(tr("--defect: %1").arg(why));
            o.defects.append({slave, *spec});
        } else if (arg == QLatin1String("--motor")) {
            if (!value(&v))
                return failed(tr("--motor needs a list such as inertia=2e-4,load=0.05"));
            QString why;
            const std::optional<DcMotor::Model> model = DcMotor::Model::parse(v, o.motor, &why);
            if (!model)
                return failed(tr("--motor: %1").arg(why));
            o.motor = *model;
        } else if (arg == QLatin1String("--quiet") || arg == QLatin1String("-q")) {
            o.quiet = true;
        } else {
            return failed(tr("unknown argument '%1'; options: --devices, --pty, --tcp, --baud, "
                             "--parity, --wire-timing, --half-duplex, --turnaround, --faults, "
                             "--seed, --defect, --motor, "
                             "--quiet, "
                             "--help, --version")
                              .arg(arguments.at(i)));
        }
    }
    if (!o.help && !o.version && o.devices.isEmpty())
        return failed(tr("--devices SPEC is required, e.g. --devices dbu200@1,dcpid@7"));
    if (!o.pty && !o.tcp)
        o.pty = true;
    return o;
}

} // namespace opentop
