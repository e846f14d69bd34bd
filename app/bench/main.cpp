// opentop-bench: performance figures of the engine on a realistic line. Starts opentop-sim (next
// to this executable) with wire timing on a pty, talks to it through the real RTU backend and
// prints plain figures with units. Exits non-zero when a benchmark fails.
//
// Each figure comes from a named benchmark in benchmarks() below.
#include "ConnectionSettings.h"
#include "ModbusClient.h"
#include "RtuBackend.h"
#include "bus/BusScanner.h"
#include "bus/BusSpec.h"
#include "eol/EolRun.h"
#include "eol/RecipeBuilder.h"
#include "files/BackupReader.h"
#include "profile/ProfileRegistry.h"
#include "session/DeviceSession.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QEventLoop>
#include <QProcess>
#include <QTextStream>
#include <QTimer>
#include <algorithm>
#include <functional>

using namespace opentop;

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::Bench", text);
}

// One measured number: "scan.full.time 8.31 s".
struct Figure
{
    QString name;
    double value = 0;
    QString unit;
    int decimals = 1;
};

// What every benchmark gets: an open connection to the simulator and the bus it simulates.
struct BenchBus
{
    ConnectionSettings settings;
    ModbusClient* client = nullptr;
    QVector<BusSpecEntry> devices;
};

// Returns false with *error when the run failed (a wrong result counts as a failure).
using BenchRun = std::function<bool(BenchBus& bus, QVector<Figure>* figures, QString* error)>;

struct Benchmark
{
    QString name;
    QString description;
    BenchRun run;
};

struct ScanRun
{
    QVector<DeviceInfo> found;
    int requests = 0;
    int lateAnswers = 0;
    double elapsedMs = 0;
    int waitMs = 0;
};

bool scan(BenchBus& bus, int from, int to, ScanRun* run, QString* error)
{
    BusScanner scanner(bus.client, ProfileRegistry::builtIn());
    scanner.setRange(from, to);
    QEventLoop loop;
    QObject::connect(&scanner, &BusScanner::finished, &loop, &QEventLoop::quit);
    QTimer::singleShot(120000, &loop, &QEventLoop::quit);
    scanner.start();
    if (scanner.isRunning())
        loop.exec();
    if (scanner.isRunning() || !scanner.error().isEmpty() || scanner.wasCancelled()) {
        *error = scanner.error().isEmpty() ? tr("the scan did not finish within 120 s")
                                           : scanner.error();
        return false;
    }
    run->found = scanner.devices();
    run->requests = scanner.requestsSent();
    run->lateAnswers = scanner.lateAnswers();
    run->elapsedMs = scanner.elapsedMs();
    run->waitMs = scanner.waitMs();
    return true;
}

bool fullScan(BenchBus& bus, QVector<Figure>* figures, QString* error)
{
    ScanRun run;
    if (!scan(bus, 1, 247, &run, error))
        return false;
    QVector<int> expected;
    for (const BusSpecEntry& e : bus.devices)
        expected << e.slave;
    std::sort(expected.begin(), expected.end());
    QVector<int> present;
    for (const DeviceInfo& info : run.found) {
        if (info.state == DeviceInfo::State::Present)
            present << info.slave;
    }
    if (present != expected || run.found.size() != expected.size()) {
        QStringList got;
        for (const DeviceInfo& info : run.found)
            got << QStringLiteral("%1 (%2)").arg(info.slave).arg(DeviceInfo::stateText(info.state));
        *error = tr("found %1, expected the drives at %2")
                     .arg(got.isEmpty() ? tr("nothing") : got.join(QStringLiteral(", ")),
                          BusSpec::toString(bus.devices));
        return false;
    }
    *figures << Figure{QStringLiteral("scan.full.time"), run.elapsedMs / 1000.0,
                       QStringLiteral("s"), 2}
             << Figure{QStringLiteral("scan.full.requests"), double(run.requests), QString(), 0}
             << Figure{QStringLiteral("scan.full.drives"), double(run.found.size()), QString(), 0}
             << Figure{QStringLiteral("scan.full.late_answers"), double(run.lateAnswers), QString(),
                       0}
             << Figure{QStringLiteral("scan.wait"), double(run.waitMs), QStringLiteral("ms"), 0};
    return true;
}

bool absentAddresses(BenchBus& bus, QVector<Figure>* figures, QString* error)
{
    // The longest run of machine numbers nobody has, at most 50 of them.
    QVector<bool> used(248, false);
    for (const BusSpecEntry& e : bus.devices)
        used[e.slave] = true;
    int bestFrom = 0;
    int bestLength = 0;
    for (int from = 1; from <= 247;) {
        int to = from;
        while (to <= 247 && !used[to])
            ++to;
        if (to - from > bestLength) {
            bestFrom = from;
            bestLength = to - from;
        }
        from = to + 1;
    }
    bestLength = std::min(bestLength, 50);
    if (bestLength < 5) {
        *error = tr("the simulated bus leaves no 5 free machine numbers in a row");
        return false;
    }
    ScanRun run;
    if (!scan(bus, bestFrom, bestFrom + bestLength - 1, &run, error))
        return false;
    if (!run.found.isEmpty()) {
        *error = tr("machine number %1 answered, but nobody is configured there")
                     .arg(run.found.first().slave);
        return false;
    }
    *figures << Figure{QStringLiteral("scan.absent.per_address"), run.elapsedMs / bestLength,
                       QStringLiteral("ms"), 1}
             << Figure{QStringLiteral("scan.absent.requests_per_address"),
                       double(run.requests) / bestLength, QString(), 2};
    return true;
}

// A single-drive backup of the first drive of each family on the bus: the time a field
// engineer waits, and how many requests it takes at the line's speed.
bool backups(BenchBus& bus, QVector<Figure>* figures, QString* error)
{
    QStringList done;
    for (const BusSpecEntry& e : bus.devices) {
        QString variant;
        const Profile* profile = ProfileRegistry::builtIn().forDeviceType(e.type, &variant);
        if (!profile || done.contains(profile->family))
            continue;
        done << profile->family;
        DeviceSession session(bus.client, *profile, e.slave, variant);
        BackupReader reader(&session);
        BackupReader::Result result;
        QEventLoop loop;
        bool finished = false;
        reader.read([&](const BackupReader::Result& r) {
            result = r;
            finished = true;
            loop.quit();
        });
        QTimer::singleShot(60000, &loop, &QEventLoop::quit);
        if (!finished)
            loop.exec();
        if (!finished || !result.ok) {
            *error = tr("backup of machine number %1 failed: %2")
                         .arg(e.slave)
                         .arg(finished ? result.failures.join(QStringLiteral("; "))
                                       : tr("no result within 60 s"));
            return false;
        }
        const QString key = QStringLiteral("backup.") + profile->family;
        *figures << Figure{key + QStringLiteral(".time"), double(result.elapsedMs),
                           QStringLiteral("ms"), 0}
                 << Figure{key + QStringLiteral(".requests"), double(result.requests), QString(), 0}
                 << Figure{key + QStringLiteral(".settings"), double(result.parameters), QString(),
                           0};
    }
    if (done.isEmpty()) {
        *error = tr("no drive of a profiled family on the bus");
        return false;
    }
    return true;
}

// opentop-sim on a pty, stopped when this goes.
class SimulatorProcess
{
public:
    ~SimulatorProcess()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(5000))
            m_process.kill();
    }

    bool start(const QStringList& arguments, QString* pty, QString* error)
    {
        m_process.setProgram(QCoreApplication::applicationDirPath() +
                             QStringLiteral("/opentop-sim"));
        m_process.setArguments(arguments);
        m_process.start();
        if (!m_process.waitForStarted(5000)) {
            *error = tr("cannot start %1: %2").arg(m_process.program(), m_process.errorString());
            return false;
        }
        for (;;) {
            while (!m_process.canReadLine()) {
                if (!m_process.waitForReadyRead(10000)) {
                    *error = tr("opentop-sim did not get ready: %1")
                                 .arg(QString::fromLocal8Bit(m_process.readAllStandardError()));
                    return false;
                }
            }
            const QString line = QString::fromLocal8Bit(m_process.readLine()).trimmed();
            if (line.startsWith(QLatin1String("pty: ")))
                *pty = line.mid(5);
            else if (line == QLatin1String("ready"))
                return !pty->isEmpty();
        }
    }

private:
    QProcess m_process;
};

// One unit of a DBU200 product through the end-of-line run (EolRun: identify, write what
// differs, read back, test), for one drive and for eight on one bus, each on its own simulator
// with wire timing at the chosen line speed. The drives run concurrently, so eight should take
// far less than eight times one; the goal is at most twice.
bool eolUnit(const ConnectionSettings& base, int drives, double* ms, QString* error)
{
    const Profile* dbu = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    Recipe recipe;
    recipe.product = QStringLiteral("bench");
    recipe.revision = QStringLiteral("A");
    for (int id = 1; id <= drives; ++id) {
        RecipePosition p;
        p.machineNumber = id;
        p.family = QStringLiteral("dbu");
        p.variants << QStringLiteral("dbu200");
        p.settings << RecipeSetting{QStringLiteral("spno2.speed"), 1500, QString()}
                   << RecipeSetting{QStringLiteral("spno2.accel"), 1.0, QString()}
                   << RecipeSetting{QStringLiteral("spno2.decel"), 2.0, QString()}
                   << RecipeSetting{QStringLiteral("spno2.direction"), QStringLiteral("CW"),
                                    QString()}
                   << RecipeSetting{QStringLiteral("spno3.speed"), 1200, QString()}
                   << RecipeSetting{QStringLiteral("alarm.load_warning"), 90, QString()};
        p.steps = RecipeBuilder::defaultSteps(*dbu, p);
        recipe.positions << p;
    }
    SimulatorProcess sim;
    ConnectionSettings settings = base;
    if (!sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1-%1").arg(drives),
                    QStringLiteral("--wire-timing"), QStringLiteral("--baud"),
                    QString::number(settings.baud), QStringLiteral("--quiet")},
                   &settings.port, error))
        return false;
    ModbusClient client(std::make_unique<RtuBackend>(settings), settings);
    *error = client.openBlocking();
    if (!error->isEmpty())
        return false;
    EolRun::Options options;
    options.serial = QStringLiteral("BENCH-%1").arg(drives);
    EolRun run(&client, ProfileRegistry::builtIn(), recipe, options);
    UnitRecord record;
    bool finished = false;
    QEventLoop loop;
    run.start([&](const UnitRecord& r) {
        record = r;
        finished = true;
        loop.quit();
    });
    QTimer::singleShot(180000, &loop, &QEventLoop::quit);
    if (!finished)
        loop.exec();
    if (!finished || !record.isPass()) {
        *error = finished ? tr("the unit of %1 drive(s) did not pass: %2")
                                .arg(drives)
                                .arg(record.failureReason)
                          : tr("the unit of %1 drive(s) did not finish within 180 s").arg(drives);
        return false;
    }
    *ms = double(run.elapsedMs());
    return true;
}

bool eolUnits(BenchBus& bus, QVector<Figure>* figures, QString* error)
{
    double one = 0;
    double eight = 0;
    if (!eolUnit(bus.settings, 1, &one, error) || !eolUnit(bus.settings, 8, &eight, error))
        return false;
    *figures << Figure{QStringLiteral("eol.unit.1_drive"), one / 1000.0, QStringLiteral("s"), 2}
             << Figure{QStringLiteral("eol.unit.8_drives"), eight / 1000.0, QStringLiteral("s"), 2}
             << Figure{QStringLiteral("eol.unit.ratio_8_to_1"), eight / one, QString(), 2};
    if (eight > 2 * one) {
        *error = tr("eight drives took %1 times as long as one; the goal is at most 2")
                     .arg(eight / one, 0, 'f', 2);
        return false;
    }
    return true;
}

// The benchmarks, in the order they run; a new figure is one more entry (name, description,
// run function).
QVector<Benchmark> benchmarks()
{
    return {
        {QStringLiteral("scan"), tr("full scan of machine numbers 1–247"), fullScan},
        {QStringLiteral("scan-absent"), tr("time per machine number nobody answers"),
         absentAddresses},
        {QStringLiteral("backup"), tr("single-drive backup of each family's first drive"), backups},
        {QStringLiteral("eol"),
         tr("end-of-line unit: one DBU200, then eight on one bus (own simulators)"), eolUnits},
    };
}

} // namespace

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("opentop-bench"));
    QTextStream out(stdout);
    QTextStream err(stderr);

    QCommandLineParser parser;
    parser.setApplicationDescription(tr("Performance figures against opentop-sim with wire "
                                        "timing on a pty."));
    parser.addHelpOption();
    parser.addOptions({
        {QStringLiteral("devices"), tr("Simulated bus (default dbu200@1,dbu400@150,dcpid@7)."),
         tr("SPEC"), QStringLiteral("dbu200@1,dbu400@150,dcpid@7")},
        {QStringLiteral("baud"), tr("Line speed the simulator times frames at (default 19200)."),
         tr("BAUD"), QStringLiteral("19200")},
        {QStringLiteral("list"), tr("List the benchmarks and exit.")},
    });
    parser.addPositionalArgument(QStringLiteral("NAME"), tr("Benchmarks to run (default all)."),
                                 QStringLiteral("[NAME...]"));
    parser.process(app);

    QVector<Benchmark> selected;
    for (const Benchmark& b : benchmarks()) {
        if (parser.isSet(QStringLiteral("list")))
            out << b.name.leftJustified(14) << b.description << '\n';
        else if (parser.positionalArguments().isEmpty() ||
                 parser.positionalArguments().contains(b.name))
            selected << b;
    }
    if (parser.isSet(QStringLiteral("list")))
        return 0;
    if (selected.size() < parser.positionalArguments().size() || selected.isEmpty()) {
        err << tr("opentop-bench: unknown benchmark; see --list") << Qt::endl;
        return 2;
    }

    BenchBus bus;
    QString error;
    const auto devices = BusSpec::parse(parser.value(QStringLiteral("devices")), &error);
    bool baudOk = false;
    bus.settings.baud = parser.value(QStringLiteral("baud")).toInt(&baudOk);
    if (!devices || !baudOk) {
        err << tr("opentop-bench: %1").arg(devices ? tr("--baud must be a number") : error)
            << Qt::endl;
        return 2;
    }
    bus.devices = *devices;
    SimulatorProcess sim;
    bus.settings.kind = ConnectionSettings::Kind::Serial;
    bus.settings.parity = 'N'; // ptys refuse E and O
    if (!sim.start({QStringLiteral("--devices"), BusSpec::toString(bus.devices),
                    QStringLiteral("--wire-timing"), QStringLiteral("--baud"),
                    QString::number(bus.settings.baud), QStringLiteral("--quiet")},
                   &bus.settings.port, &error)) {
        err << tr("opentop-bench: %1").arg(error) << Qt::endl;
        return 1;
    }
    ModbusClient client(std::make_unique<RtuBackend>(bus.settings), bus.settings);
    error = client.openBlocking();
    if (!error.isEmpty()) {
        err << tr("opentop-bench: %1").arg(error) << Qt::endl;
        return 1;
    }
    bus.client = &client;
    out << tr("opentop-sim %1 on %2, wire timing, RTU backend")
               .arg(BusSpec::toString(bus.devices), client.describe())
        << Qt::endl;

    int failed = 0;
    for (const Benchmark& b : selected) {
        QVector<Figure> figures;
        if (!b.run(bus, &figures, &error)) {
            err << tr("%1: FAILED: %2").arg(b.name, error) << Qt::endl;
            ++failed;
            continue;
        }
        for (const Figure& f : figures)
            out << QStringLiteral("%1 %2%3").arg(
                       f.name.leftJustified(36), QString::number(f.value, 'f', f.decimals),
                       f.unit.isEmpty() ? QString() : QLatin1Char(' ') + f.unit)
                << Qt::endl;
    }
    return failed ? 1 : 0;
}
