// Issue 25 item 4, in the real window: a unit the station could not test (no drive, a motor
// already turning, an alarm latched before the test) is a station error, never a FAIL, and is
// kept out of yield; the screen's figures are the ones `opentop-cli eol results --yield` prints
// for the same station, recipe version and shift; an alarm latched before the test is reset
// from the screen and the unit tested again; a serial that passed waits for a technician.
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/StationYield.h"
#include "model/eol/YieldReport.h"
#include "model/station/EolStation.h"
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/eol/ProductionMode.h"
#include "ui/eol/ProductionView.h"
#include "ui/eol/StationActions.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

class MainWindowStationYieldTest : public MainWindowFixture
{
protected:
    void SetUp() override
    {
        MainWindowFixture::SetUp();
        db = dir.filePath(QStringLiteral("results.db"));
        qputenv("OPENTOP_EOL_DB", db.toLocal8Bit());
        window->production()->toggleAction()->trigger();
        qunsetenv("OPENTOP_EOL_DB");
        station = window->production()->station();
        view = window->production()->view();
        ASSERT_TRUE(waitFor([&] { return station->hasDatabase(); }));
        // The example DBU200 recipe for drive 1 with a 1 s hold and no per-unit values.
        QString error;
        std::optional<Recipe> recipe = RecipeFile::load(
            QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error);
        ASSERT_TRUE(recipe) << qPrintable(error);
        recipe->positions[0].unitValues.clear();
        for (RecipeStep& s : recipe->positions[0].steps)
            if (s.type == RecipeStep::Type::Hold)
                s.duration = 1;
        const QString path = dir.filePath(QStringLiteral("recipe.json"));
        ASSERT_TRUE(RecipeFile::save(*recipe, path, &error)) << qPrintable(error);
        ASSERT_TRUE(view->openRecipe(path));
        ASSERT_TRUE(waitFor([&] { return station->isSafe(); }, 10000));
    }

    // Scans `serial` and waits for the screen's next verdict.
    QString scan(const QString& serial)
    {
        const int rows = view->unitsTable()->rowCount();
        QTest::keyClicks(view->serialField(), serial);
        QTest::keyClick(view->serialField(), Qt::Key_Return);
        const bool ended = waitFor(
            [&] {
                return (view->unitsTable()->rowCount() > rows ||
                        view->verdictLabel()->text() == QLatin1String("NOT STARTED")) &&
                       !station->isRunning() && !station->isStarting();
            },
            30000);
        EXPECT_TRUE(ended) << qPrintable(serial);
        return view->verdictLabel()->text();
    }

    QVector<UnitRecord> history(const QString& serial)
    {
        QString error;
        const auto database = ResultDatabase::open(db, &error);
        EXPECT_TRUE(database) << qPrintable(error);
        return database ? ResultQueries(*database)
                              .history(serial, &error)
                              .value_or(QVector<UnitRecord>())
                        : QVector<UnitRecord>();
    }

    QTemporaryDir dir;
    QString db;
    EolStation* station = nullptr;
    ProductionView* view = nullptr;
};

} // namespace

TEST_F(MainWindowStationYieldTest, StationErrorsAreNoVerdictsAndTheScreensYieldIsTheReports)
{
    EXPECT_EQ(scan(QStringLiteral("SN-A")), QStringLiteral("PASS"));
    bus->control(1, {QStringLiteral("load"), QStringLiteral("90")});
    EXPECT_EQ(scan(QStringLiteral("SN-B")), QStringLiteral("FAIL"))
        << qPrintable(view->reasonLabel()->text());
    bus->control(1, {QStringLiteral("load"), QStringLiteral("0")});
    // A motor turning before the test: the station's problem, not the unit's. The screen says
    // so in a box as well (the motor may still turn): accepted here.
    QStringList boxes;
    QTimer dismiss;
    QObject::connect(&dismiss, &QTimer::timeout, [&boxes] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            boxes << box->text();
            box->accept();
        }
    });
    dismiss.start(50);
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0; }));
    EXPECT_EQ(scan(QStringLiteral("SN-C")), QStringLiteral("STATION ERROR"))
        << qPrintable(view->reasonLabel()->text());
    EXPECT_TRUE(view->reasonLabel()->text().contains(QStringLiteral("already running")))
        << qPrintable(view->reasonLabel()->text());
    EXPECT_EQ(boxes.size(), 1) << "the motor found turning is named";
    // The station stops what it found turning before the next unit.
    ASSERT_TRUE(waitFor([&] { return station->isSafe() && speedOf(1) == 0; }, 10000));
    EXPECT_EQ(scan(QStringLiteral("SN-C")), QStringLiteral("PASS"));
    EXPECT_EQ(scan(QStringLiteral("SN-B")), QStringLiteral("PASS"));

    const QVector<UnitRecord> c = history(QStringLiteral("SN-C"));
    ASSERT_EQ(c.size(), 2);
    EXPECT_EQ(c[0].status, UnitStatus::Error);
    EXPECT_EQ(c[1].attempt, 1) << "a station error is no attempt";
    const QVector<UnitRecord> b = history(QStringLiteral("SN-B"));
    ASSERT_EQ(b.size(), 2);
    EXPECT_EQ(b[1].attempt, 2);

    ASSERT_TRUE(waitFor(
        [&] {
            return view->countersLabel()->text().startsWith(
                QStringLiteral("This shift: tested 4 · passed 3 · failed 1 · station errors 1"));
        },
        5000))
        << qPrintable(view->countersLabel()->text());
    const YieldRow screen = station->yield()->row();
    EXPECT_EQ(screen.serials, 3);
    EXPECT_EQ(screen.firstPass, 2); // SN-A, and SN-C: its station error was no verdict
    EXPECT_TRUE(view->countersLabel()->text().contains(YieldReport::yieldText(screen)));

    // The same figures from the command line, by the command the tooltip gives.
    QStringList args{
        QStringLiteral("eol"),
        QStringLiteral("results"),
        QStringLiteral("--yield"),
        QStringLiteral("--json"),
        QStringLiteral("--db"),
        db,
        QStringLiteral("--station"),
        station->station(),
        QStringLiteral("--checksum"),
        c[1].recipeChecksum,
        QStringLiteral("--since"),
        station->yield()->shiftStart().toLocalTime().toString(QStringLiteral("yyyy-MM-ddTHH:mm"))};
    EXPECT_TRUE(view->countersLabel()->toolTip().contains(station->yield()->commandLine()));
    QProcess cli;
    cli.start(QStringLiteral(OPENTOP_BIN_DIR "/opentop-cli"), args);
    ASSERT_TRUE(cli.waitForFinished(30000));
    ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
    const QJsonArray rows = QJsonDocument::fromJson(cli.readAllStandardOutput())
                                .object()
                                .value(QStringLiteral("perRecipe"))
                                .toArray();
    ASSERT_EQ(rows.size(), 1);
    const QJsonObject row = rows.at(0).toObject();
    EXPECT_EQ(row.value(QStringLiteral("serials")).toInt(), screen.serials);
    EXPECT_EQ(row.value(QStringLiteral("firstPass")).toInt(), screen.firstPass);
    EXPECT_EQ(row.value(QStringLiteral("secondPass")).toInt(), screen.secondPass);
    EXPECT_EQ(row.value(QStringLiteral("lastPass")).toInt(), screen.lastPass);
    EXPECT_EQ(row.value(QStringLiteral("stationErrors")).toInt(), 1);
    EXPECT_EQ(row.value(QStringLiteral("failed")).toInt(), 1);
    EXPECT_EQ(screen.secondPass, 3);
    EXPECT_EQ(screen.lastPass, 3);
}

TEST_F(MainWindowStationYieldTest, AnAlarmLatchedBeforeTheTestIsResetFromTheScreenAndTheUnitRuns)
{
    bus->control(1, {QStringLiteral("alarm"), QStringLiteral("3")}); // overcurrent, resettable
    EXPECT_EQ(scan(QStringLiteral("SN-AL")), QStringLiteral("STATION ERROR"))
        << qPrintable(view->reasonLabel()->text());
    EXPECT_TRUE(view->reasonLabel()->text().contains(QStringLiteral("alarm is active")))
        << qPrintable(view->reasonLabel()->text());
    QPushButton* reset = view->actions()->resetButton();
    ASSERT_TRUE(waitFor([&] { return reset->isVisible(); }));
    EXPECT_TRUE(view->actions()->textLabel()->text().contains(QStringLiteral("machine number 1")));
    const int rows = view->unitsTable()->rowCount();
    reset->click();
    // Reset, then the same serial tested again by itself.
    ASSERT_TRUE(waitFor(
        [&] { return view->unitsTable()->rowCount() > rows && !station->isRunning(); }, 30000))
        << qPrintable(view->actions()->textLabel()->text());
    EXPECT_EQ(view->verdictLabel()->text(), QStringLiteral("PASS"))
        << qPrintable(view->reasonLabel()->text());
    const QVector<UnitRecord> h = history(QStringLiteral("SN-AL"));
    ASSERT_EQ(h.size(), 2);
    EXPECT_EQ(h[0].status, UnitStatus::Error);
    EXPECT_TRUE(h[0].writtenValues.isEmpty()) << "nothing was written before the reset";
    EXPECT_EQ(h[1].status, UnitStatus::Pass);
    EXPECT_EQ(h[1].attempt, 1);
}

TEST_F(MainWindowStationYieldTest, APassedSerialScannedAgainWaitsForATechnician)
{
    EXPECT_EQ(scan(QStringLiteral("SN-P")), QStringLiteral("PASS"));
    EXPECT_EQ(scan(QStringLiteral("SN-P")), QStringLiteral("NOT STARTED"));
    EXPECT_TRUE(view->reasonLabel()->text().contains(QStringLiteral("passed already")))
        << qPrintable(view->reasonLabel()->text());
    EXPECT_EQ(speedOf(1), 0);
    QPushButton* retest = view->actions()->retestButton();
    ASSERT_TRUE(waitFor([&] { return retest->isVisible(); }));
    EXPECT_EQ(history(QStringLiteral("SN-P")).size(), 1) << "nothing recorded, nothing sent";

    // The technician allows it (an unmanaged station: whoever is at the screen, named).
    auto* timer = new QTimer;
    QObject::connect(timer, &QTimer::timeout, [timer] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            box->button(QMessageBox::Yes)->click();
            timer->deleteLater();
        }
    });
    timer->start(20);
    const int rows = view->unitsTable()->rowCount();
    retest->click();
    ASSERT_TRUE(waitFor(
        [&] { return view->unitsTable()->rowCount() > rows && !station->isRunning(); }, 30000));
    EXPECT_EQ(view->verdictLabel()->text(), QStringLiteral("PASS"));
    const QVector<UnitRecord> h = history(QStringLiteral("SN-P"));
    ASSERT_EQ(h.size(), 2);
    EXPECT_EQ(h[1].attempt, 2);
}
