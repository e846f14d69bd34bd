#include "tests/soak/SoakOptions.h"

namespace opentop::soak {

QString SoakOptions::defaultDevices()
{
    return QStringLiteral("dcpid@1-40,dbu200@41-140,dbu400@141-247");
}

QString SoakOptions::usage()
{
    return QStringLiteral(
               "Usage: opentop-soak [options]\n"
               "Monitors every drive of a simulated bus (opentop-sim on a pty, through libmodbus) "
               "with\n"
               "the model's monitor hub in this process and with the opentop program (bus overview "
               "and\n"
               "trends open, offscreen), and prints each process's resident memory, open file\n"
               "descriptors, threads and samples per second at every interval. Exits 1 naming the "
               "goal\n"
               "missed: RSS growth of 5 % or more after the warm-up (5 min, or 20 % of a shorter "
               "run),\n"
               "file descriptor or thread growth, or an unsteady sample rate.\n\n"
               "  --minutes N            monitoring time (60)\n"
               "  --interval-seconds S   between figure lines (60)\n"
               "  --warmup-seconds S     before the figures judged (5 min, or 20 % of a shorter "
               "run)\n"
               "  --devices SPEC         the simulated bus (%1)\n"
               "  --baud N               line speed, simulated with --wire-timing (115200)\n"
               "  --poll-ms MS           poll interval per drive (10000)\n"
               "  --no-gui               only the monitor hub in this process\n"
               "  --no-model             only the opentop program\n"
               "  --bin-dir DIR          where opentop and opentop-sim are (%2)\n"
               "  --help                 this text\n")
        .arg(defaultDevices(), QStringLiteral(OPENTOP_BIN_DIR));
}

std::optional<SoakOptions> SoakOptions::parse(const QStringList& arguments, QString* error,
                                              bool* help)
{
    SoakOptions o;
    o.binDir = QStringLiteral(OPENTOP_BIN_DIR);
    *help = false;
    auto failed = [error](const QString& text) {
        *error = text;
        return std::nullopt;
    };
    for (int i = 0; i < arguments.size(); ++i) {
        const QString arg = arguments.at(i);
        auto value = [&](QString* out) {
            if (i + 1 >= arguments.size())
                return false;
            *out = arguments.at(++i);
            return true;
        };
        auto number = [&](double* out, double min, double max) {
            QString v;
            bool ok = false;
            const double d = value(&v) ? v.toDouble(&ok) : 0;
            if (!ok || d < min || d > max)
                return false;
            *out = d;
            return true;
        };
        double d = 0;
        if (arg == QLatin1String("--help") || arg == QLatin1String("-h")) {
            *help = true;
            return o;
        } else if (arg == QLatin1String("--minutes")) {
            if (!number(&o.minutes, 0.1, 10000))
                return failed(QStringLiteral("--minutes needs a number of minutes, 0.1 or more"));
        } else if (arg == QLatin1String("--interval-seconds")) {
            if (!number(&o.intervalSeconds, 1, 3600))
                return failed(QStringLiteral("--interval-seconds needs 1..3600 seconds"));
        } else if (arg == QLatin1String("--warmup-seconds")) {
            if (!number(&o.warmupSeconds, 0, 600000))
                return failed(QStringLiteral("--warmup-seconds needs a number of seconds"));
        } else if (arg == QLatin1String("--devices")) {
            if (!value(&o.devices) || o.devices.isEmpty())
                return failed(QStringLiteral("--devices needs a list such as dbu200@1-247"));
        } else if (arg == QLatin1String("--baud")) {
            if (!number(&d, 1200, 115200))
                return failed(QStringLiteral("--baud needs a line speed 1200..115200"));
            o.baud = int(d);
        } else if (arg == QLatin1String("--poll-ms")) {
            if (!number(&d, 20, 600000))
                return failed(QStringLiteral("--poll-ms needs 20..600000 ms"));
            o.pollMs = int(d);
        } else if (arg == QLatin1String("--no-gui")) {
            o.gui = false;
        } else if (arg == QLatin1String("--no-model")) {
            o.model = false;
        } else if (arg == QLatin1String("--bin-dir")) {
            if (!value(&o.binDir))
                return failed(QStringLiteral("--bin-dir needs a directory"));
        } else {
            return failed(QStringLiteral("unknown argument \"%1\" (see --help)").arg(arg));
        }
    }
    if (!o.gui && !o.model)
        return failed(QStringLiteral("--no-gui and --no-model leave nothing to measure"));
    if (o.intervalSeconds > o.minutes * 60)
        return failed(QStringLiteral("--interval-seconds is longer than the run"));
    if (o.warmupSeconds >= o.minutes * 60)
        return failed(QStringLiteral("--warmup-seconds leaves nothing of the run to judge"));
    return o;
}

} // namespace opentop::soak
