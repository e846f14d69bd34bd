#include "bench/EolBenchmark.h"

#include "bench/BenchReport.h"
#include "bench/SimulatorProcess.h"
#include "model/eol/EolRun.h"
#include "model/eol/RecipeBuilder.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusClient.h"
#include "transport/RtuBackend.h"

#include <QEventLoop>
#include <QTimer>

namespace opentop {

namespace {

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
                    QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex"),
                    QStringLiteral("--baud"), QString::number(settings.baud)},
                   error))
        return false;
    settings.port = sim.pty();
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
        *error =
            finished
                ? QStringLiteral("the unit of %1 drive(s) did not pass: %2")
                      .arg(drives)
                      .arg(record.failureReason)
                : QStringLiteral("the unit of %1 drive(s) did not finish within 180 s").arg(drives);
        return false;
    }
    *ms = double(run.elapsedMs());
    return true;
}

} // namespace

QString EolBenchmark::description() const
{
    return QStringLiteral("end-of-line unit: one DBU200, then eight on one bus (own simulators)");
}

bool EolBenchmark::run(const BenchEnvironment&, BenchReport& report, QString* error)
{
    ConnectionSettings base;
    base.kind = ConnectionSettings::Kind::Serial;
    base.baud = 19200;
    base.parity = 'N'; // ptys refuse E and O
    double one = 0;
    double eight = 0;
    if (!eolUnit(base, 1, &one, error) || !eolUnit(base, 8, &eight, error))
        return false;
    report.add(BenchFigure::plain(QStringLiteral("eol.unit.1_drive"), one / 1000.0,
                                  QStringLiteral("s"), 2, QStringLiteral("19200 bit/s")));
    report.add(BenchFigure::plain(QStringLiteral("eol.unit.8_drives"), eight / 1000.0,
                                  QStringLiteral("s"), 2));
    report.add(BenchFigure::atMost(QStringLiteral("eol.unit.ratio_8_to_1"), eight / one,
                                   QStringLiteral("x"), 2.0, 2));
    return true;
}

} // namespace opentop
