// A test station for the results database (tests/model/eol):
//   opentop-eol-db-writer write URL STATION COUNT   COUNT units, each begun and finished
//   opentop-eol-db-writer hang URL STATION SERIAL   begins a unit, then stops inside
//       finishUnit's transaction (children written, status not) after printing "in-transaction",
//       and waits there to be killed
// Each unit has two drives, three written values, three measurements and, when it fails, two
// traffic lines; unit i of a station fails when i % 5 == 4. Exit status 0, or 1 with the error.
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultStore.h"

#include <QCoreApplication>
#include <QThread>
#include <cstdio>

using namespace opentop;

namespace {

UnitRecord unit(const QString& station, const QString& serial, int i)
{
    UnitRecord r;
    r.serial = serial;
    r.station = station;
    r.operatorName = QStringLiteral("op-") + station;
    r.recipeName = QStringLiteral("pump-200");
    r.recipeRevision = QStringLiteral("3");
    r.recipeChecksum = QStringLiteral("sha256:0011");
    for (int m : {1, 2})
        r.drives.append({m, QStringLiteral("DBU"), QStringLiteral("DBU200"), QStringLiteral("1.07"),
                         VariantSource::Assumed, QString()});
    for (int k = 0; k < 3; ++k)
        r.writtenValues.append({1 + k % 2, QStringLiteral("spno%1.speed").arg(k),
                                QStringLiteral("Speed %1").arg(k),
                                QStringLiteral("%1 r/min").arg(1000 + i), k != 1, true,
                                QStringLiteral("%1 r/min").arg(1000 + i)});
    const bool fails = i % 5 == 4;
    for (int k = 0; k < 3; ++k)
        r.measurements.append({1 + k % 2, QStringLiteral("hold CW"), QStringLiteral("speed mean"),
                               1495.5 + k + (fails ? 200 : 0), QStringLiteral("r/min"), 1450.0,
                               1550.0, !fails});
    r.status = fails ? UnitStatus::Fail : UnitStatus::Pass;
    if (fails) {
        r.failureReason = QStringLiteral("drive 1: speed mean %1 r/min above 1550 r/min")
                              .arg(r.measurements[0].value);
        r.traffic = {QStringLiteral("→ 01 03 0100 0002"), QStringLiteral("← 01 03 04 …")};
    }
    return r;
}

int fail(const QString& why)
{
    std::fprintf(stderr, "opentop-eol-db-writer: %s\n", qPrintable(why));
    return 1;
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 5 || (args[1] != QLatin1String("write") && args[1] != QLatin1String("hang")))
        return fail(QStringLiteral("usage: write URL STATION COUNT | hang URL STATION SERIAL"));
    QString error;
    auto db = ResultDatabase::open(args[2], &error);
    if (!db)
        return fail(error);
    ResultStore store(*db);
    const QString station = args[3];
    if (args[1] == QLatin1String("hang")) {
        UnitRecord r = unit(station, args[4], 0);
        if (!store.beginUnit(r, &error))
            return fail(error);
        std::printf("begun %s\n", qPrintable(r.id));
        std::fflush(stdout);
        store.setInTransactionHook([] {
            std::printf("in-transaction\n");
            std::fflush(stdout);
            for (;;)
                QThread::sleep(60);
        });
        store.finishUnit(r, &error);
        return fail(QStringLiteral("finishUnit returned"));
    }
    const int count = args[4].toInt();
    for (int i = 0; i < count; ++i) {
        UnitRecord r =
            unit(station, QStringLiteral("%1-%2").arg(station).arg(i, 4, 10, QLatin1Char('0')), i);
        if (!store.beginUnit(r, &error) || !store.finishUnit(r, &error))
            return fail(QStringLiteral("unit %1: %2").arg(i).arg(error));
    }
    std::printf("done %d\n", count);
    return 0;
}
