#include "tests/faultmatrix/MatrixOptions.h"

#include <QStringList>
#include <algorithm>

namespace opentop::faultmatrix {

std::optional<QVector<int>> MatrixOptions::parseList(const QString& text)
{
    QVector<int> seeds;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QStringList range = part.split(QLatin1Char('-'));
        bool ok1 = false;
        bool ok2 = true;
        const int first = range.first().toInt(&ok1);
        const int last = range.size() == 2 ? range.last().toInt(&ok2) : first;
        if (!ok1 || !ok2 || range.size() > 2 || first < 0 || last < first || last - first > 1000)
            return std::nullopt;
        for (int s = first; s <= last; ++s)
            seeds << s;
    }
    if (seeds.isEmpty())
        return std::nullopt;
    return seeds;
}

QString MatrixOptions::usage()
{
    return QStringLiteral(
        "Usage: opentop-faultmatrix [options]\n"
        "Backs up, changes, restores and compares a simulated bus through the real opentop-sim\n"
        "(--wire-timing, seeded faults, a pty) and opentop-cli (default timeout and retries),\n"
        "and counts what went wrong. Exits 1 when a must-be-0 count is not 0.\n\n"
        "  --seeds LIST      fault seeds, e.g. 1-5 or 3,7 (1-5)\n"
        "  --drives N        drives on the bus, 1..247 (32)\n"
        "  --faults LIST     opentop-sim --faults (drop=0.05,crc=0.02,late=0.02,busy=0.01)\n"
        "  --vanish          also pull the port out mid-backup and mid-restore\n"
        "  --attempts N      runs of an operation that gave up, per step (4)\n"
        "  --sabotage        change a drive behind the tool's back after the restore: the\n"
        "                    run must then fail (proves the counting can fail)\n"
        "  --self-test       check the counting rules on made-up reports, then a sabotaged\n"
        "                    run; exits 0 when every planted fault was counted\n"
        "  --baud N          the line's rate (19200)\n"
        "  --late-sweep MS   only late replies: each seed at every rate of --bauds and each\n"
        "                    delay of MS (e.g. 50,200,450,1000,2000); prints false compare\n"
        "                    rows, misreads and needless writes per delay and rate\n"
        "  --bauds LIST      the rates of --late-sweep (9600,19200,115200)\n"
        "  --late-rate R     the share of replies sent late in --late-sweep (0.10)\n"
        "  --trace-dir DIR   run opentop-cli with --trace and keep each run's trace in DIR\n"
        "  --bin-dir DIR     where opentop-sim and opentop-cli are\n"
        "  --verbose         print every command and its output\n");
}

std::optional<MatrixOptions> MatrixOptions::parse(const QStringList& arguments, QString* error)
{
    MatrixOptions o;
    o.binDir = QStringLiteral(OPENTOP_BIN_DIR);
    for (int i = 0; i < arguments.size(); ++i) {
        const QString arg = arguments.at(i);
        auto value = [&](QString* out) {
            if (i + 1 >= arguments.size()) {
                *error = QStringLiteral("%1 needs a value").arg(arg);
                return false;
            }
            *out = arguments.at(++i);
            return true;
        };
        QString v;
        if (arg == QLatin1String("--seeds")) {
            if (!value(&v))
                return std::nullopt;
            const auto seeds = parseList(v);
            if (!seeds) {
                *error = QStringLiteral("--seeds: '%1' is not a list such as 1-5 or 3,7").arg(v);
                return std::nullopt;
            }
            o.seeds = *seeds;
        } else if (arg == QLatin1String("--drives") || arg == QLatin1String("--attempts")) {
            if (!value(&v))
                return std::nullopt;
            bool ok = false;
            const int n = v.toInt(&ok);
            const int max = arg == QLatin1String("--drives") ? 247 : 20;
            if (!ok || n < 1 || n > max) {
                *error = QStringLiteral("%1 must be 1..%2, got '%3'").arg(arg).arg(max).arg(v);
                return std::nullopt;
            }
            (arg == QLatin1String("--drives") ? o.drives : o.attempts) = n;
        } else if (arg == QLatin1String("--late-sweep") || arg == QLatin1String("--bauds") ||
                   arg == QLatin1String("--baud")) {
            if (!value(&v))
                return std::nullopt;
            const auto list = parseList(v);
            const bool bauds = arg != QLatin1String("--late-sweep");
            const bool fits = list && std::all_of(list->begin(), list->end(), [&](int n) {
                                  return bauds ? n >= 1200 && n <= 115200 : n >= 1 && n <= 10000;
                              });
            if (!fits || (arg == QLatin1String("--baud") && list->size() != 1)) {
                *error = QStringLiteral("%1: '%2' is not %3")
                             .arg(arg, v,
                                  bauds ? QStringLiteral("a rate 1200..115200 (or a list)")
                                        : QStringLiteral("a list of delays 1..10000 ms"));
                return std::nullopt;
            }
            if (arg == QLatin1String("--baud"))
                o.baud = list->first();
            else
                (bauds ? o.sweepBauds : o.lateSweepMs) = *list;
        } else if (arg == QLatin1String("--late-rate")) {
            if (!value(&v))
                return std::nullopt;
            bool ok = false;
            o.lateRate = v.toDouble(&ok);
            if (!ok || o.lateRate <= 0 || o.lateRate > 0.5) {
                *error =
                    QStringLiteral("--late-rate must be above 0 and at most 0.5, got '%1'").arg(v);
                return std::nullopt;
            }
        } else if (arg == QLatin1String("--faults")) {
            if (!value(&o.faults))
                return std::nullopt;
        } else if (arg == QLatin1String("--trace-dir")) {
            if (!value(&o.traceDir))
                return std::nullopt;
        } else if (arg == QLatin1String("--bin-dir")) {
            if (!value(&o.binDir))
                return std::nullopt;
        } else if (arg == QLatin1String("--vanish")) {
            o.vanish = true;
        } else if (arg == QLatin1String("--self-test")) {
            o.selfTest = true;
        } else if (arg == QLatin1String("--sabotage")) {
            o.sabotage = true;
        } else if (arg == QLatin1String("--verbose")) {
            o.verbose = true;
        } else if (arg == QLatin1String("--help") || arg == QLatin1String("-h")) {
            *error = QString();
            return std::nullopt;
        } else {
            *error = QStringLiteral("unknown option '%1'").arg(arg);
            return std::nullopt;
        }
    }
    return o;
}

QString MatrixOptions::typeOf(int slave)
{
    if (slave % 8 == 0)
        return QStringLiteral("dcpid");
    return slave % 3 == 0 ? QStringLiteral("dbu400") : QStringLiteral("dbu200");
}

QString MatrixOptions::deviceSpec(int drives)
{
    QStringList parts;
    for (int slave = 1; slave <= drives; ++slave)
        parts << QStringLiteral("%1@%2").arg(typeOf(slave)).arg(slave);
    return parts.join(QLatin1Char(','));
}

QString MatrixOptions::variantList(int drives)
{
    QStringList parts;
    for (int slave = 1; slave <= drives; ++slave) {
        if (typeOf(slave).startsWith(QLatin1String("dbu")))
            parts << QStringLiteral("%1=%2").arg(slave).arg(typeOf(slave));
    }
    return parts.join(QLatin1Char(','));
}

} // namespace opentop::faultmatrix
