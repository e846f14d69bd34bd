// The engineers' end-of-line tools in the real window (issue 12, section 5): End of line ▸
// Results… browses a real SQLite results database (filters, first-pass yield, a unit's whole
// record, CSV, certificate PDF) and never creates a database by looking; End of line ▸ Recipe
// editor… opens, makes (from the drive on the bus), edits and checks recipes with the
// profiles' rules, and saves only a recipe that passes.
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultStore.h"
#include "tests/support/EolSampleUnit.h"
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/eol/EolMenu.h"
#include "ui/eol/GoldenMeasureButton.h"
#include "ui/eol/RecipeEditor.h"
#include "ui/eol/RecipePositionForm.h"
#include "ui/eol/RecipeStepsEditor.h"
#include "ui/eol/ResultsBrowser.h"

#include <QComboBox>
#include <QFile>
#include <QGroupBox>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>

using MainWindowEolToolsTest = opentop::test::MainWindowFixture;
using namespace opentop;
using namespace opentop::test;

namespace {

QAction* actionNamed(MainWindow* window, const QString& text)
{
    for (QAction* a : window->findChildren<QAction*>())
        if (a->text() == text)
            return a;
    return nullptr;
}

void record(ResultDatabase& db, const QString& serial, UnitStatus status)
{
    UnitRecord unit = eolSampleUnit(serial, status);
    unit.id.clear();
    unit.started = QDateTime();
    unit.ended = QDateTime();
    unit.status = UnitStatus::Running;
    QString error;
    ResultStore store(db);
    ASSERT_TRUE(store.beginUnit(unit, &error)) << qPrintable(error);
    unit.status = status;
    if (status == UnitStatus::Pass)
        unit.failureReason.clear();
    ASSERT_TRUE(store.finishUnit(unit, &error)) << qPrintable(error);
}

int settingRow(QTableWidget* table, const QString& name)
{
    for (int row = 0; row < table->rowCount(); ++row)
        if (table->item(row, 1)->text() == name)
            return row;
    return -1;
}

} // namespace

TEST_F(MainWindowEolToolsTest, ResultsShowsFiltersAndExportsWhatTheDatabaseHolds)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("results.db"));
    {
        QString error;
        auto db = ResultDatabase::open(path, &error);
        ASSERT_TRUE(db) << qPrintable(error);
        record(*db, QStringLiteral("SN-A"), UnitStatus::Pass);
        record(*db, QStringLiteral("SN-B"), UnitStatus::Fail);
        record(*db, QStringLiteral("SN-B"), UnitStatus::Pass); // a retest: no first pass
    }
    qputenv("OPENTOP_EOL_DB", path.toLocal8Bit());
    QAction* results = actionNamed(window.get(), QStringLiteral("Re&sults…"));
    ASSERT_TRUE(results);
    results->trigger();
    qunsetenv("OPENTOP_EOL_DB");
    auto* browser = window->findChild<ResultsBrowser*>();
    ASSERT_TRUE(browser);
    ASSERT_TRUE(browser->isVisible());
    // Opened and searched on the results thread: the window answers meanwhile.
    ASSERT_TRUE(waitFor([&] { return !browser->isBusy(); }));
    EXPECT_EQ(browser->table()->rowCount(), 3);
    EXPECT_TRUE(browser->summary().contains(QStringLiteral("first-pass yield 50.0 %")))
        << qPrintable(browser->summary());

    browser->verdictFilter()->setCurrentIndex(
        browser->verdictFilter()->findData(QStringLiteral("fail")));
    ASSERT_TRUE(browser->search());
    EXPECT_EQ(browser->table()->rowCount(), 0) << "the rows of the last search are gone";
    ASSERT_TRUE(waitFor([&] { return !browser->isBusy(); }));
    ASSERT_EQ(browser->table()->rowCount(), 1);
    EXPECT_EQ(browser->table()->item(0, 1)->text(), QStringLiteral("SN-B"));
    browser->table()->selectRow(0);
    QString error;
    EXPECT_FALSE(browser->saveCertificate(dir.filePath(QStringLiteral("early.pdf")), &error));
    EXPECT_EQ(error, QStringLiteral("the unit's record is still being read"));
    ASSERT_TRUE(waitFor([&] { return !browser->isBusy(); }));
    const QString details = browser->details()->toPlainText();
    EXPECT_TRUE(details.contains(QStringLiteral("SN-B"))) << qPrintable(details);
    EXPECT_TRUE(details.contains(QStringLiteral("FAIL"))) << qPrintable(details);

    const QString pdf = dir.filePath(QStringLiteral("SN-B.pdf"));
    ASSERT_TRUE(browser->saveCertificate(pdf, &error)) << qPrintable(error);
    QFile certificate(pdf);
    ASSERT_TRUE(certificate.open(QIODevice::ReadOnly));
    EXPECT_TRUE(certificate.read(5).startsWith("%PDF"));

    browser->verdictFilter()->setCurrentIndex(0);
    browser->serialFilter()->setText(QStringLiteral("SN-A"));
    ASSERT_TRUE(browser->search());
    ASSERT_TRUE(waitFor([&] { return !browser->isBusy(); }));
    ASSERT_EQ(browser->table()->rowCount(), 1);
    const QString csv = dir.filePath(QStringLiteral("units.csv"));
    ASSERT_TRUE(browser->exportCsv(csv, &error)) << qPrintable(error);
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    EXPECT_TRUE(text.contains("SN-A"));
    EXPECT_FALSE(text.contains("SN-B"));

    // Looking at a database that is not there says so and leaves no file behind.
    const QString missing = dir.filePath(QStringLiteral("typo.db"));
    EXPECT_FALSE(browser->openDatabase(missing));
    EXPECT_FALSE(QFile::exists(missing));
    EXPECT_EQ(browser->table()->rowCount(), 0);
    browser->close();
}

TEST_F(MainWindowEolToolsTest, RecipeEditorChecksEveryEditAndSavesOnlyARecipeThatPasses)
{
    QAction* open = actionNamed(window.get(), QStringLiteral("&Recipe editor…"));
    ASSERT_TRUE(open);
    open->trigger();
    auto* editor = window->findChild<RecipeEditor*>();
    ASSERT_TRUE(editor);
    // Empty, it cannot be saved and says how to begin.
    EXPECT_FALSE(editor->check().isEmpty());
    QString error;
    ASSERT_TRUE(editor->openFile(
        QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error))
        << qPrintable(error);
    EXPECT_TRUE(editor->check().isEmpty());

    // A speed the DBU200 cannot run: named with the allowed values, and nothing saved.
    QTableWidget* settings = editor->positionForm()->settingsTable();
    const int row = settingRow(settings, QStringLiteral("spno2.speed"));
    ASSERT_GE(row, 0);
    settings->item(row, 2)->setText(QStringLiteral("99999"));
    const QVector<RecipeProblem> problems = editor->check();
    ASSERT_EQ(problems.size(), 1);
    EXPECT_TRUE(problems.first().message.contains(QStringLiteral("SPno2")))
        << qPrintable(problems.first().message);
    EXPECT_TRUE(problems.first().message.contains(QStringLiteral("r/min")))
        << qPrintable(problems.first().message);
    EXPECT_EQ(editor->problemsList()->count(), 1);
    // Activating the problem selects the setting it names.
    settings->clearSelection();
    emit editor->problemsList()->itemActivated(editor->problemsList()->item(0));
    EXPECT_EQ(settings->currentRow(), row)
        << qPrintable(editor->problemsList()->item(0)->data(Qt::UserRole).toString());
    QTemporaryDir dir;
    const QString saved = dir.filePath(QStringLiteral("c200-b.json"));
    EXPECT_FALSE(editor->saveTo(saved, &error));
    EXPECT_FALSE(QFile::exists(saved));

    // The steps as a table and a form per step, as an engineer edits them. A tolerance wider
    // than the target: the checker names it and its problem selects the step.
    RecipeStepsEditor* steps = editor->positionForm()->stepsEditor();
    ASSERT_EQ(steps->table()->rowCount(), 8);
    EXPECT_EQ(steps->table()->item(3, 1)->text(), QStringLiteral("Wait for speed")); // the table's
    EXPECT_EQ(steps->table()->item(3, 2)->text(), QStringLiteral("1500 ± 50 r/min within 5 s"));
    steps->select(3);
    auto* tolerance = steps->detail()->findChild<QLineEdit*>(QStringLiteral("step_tolerance"));
    ASSERT_TRUE(tolerance);
    tolerance->selectAll();
    QTest::keyClicks(tolerance, QStringLiteral("2000"));
    EXPECT_EQ(steps->table()->item(3, 2)->text(), QStringLiteral("1500 ± 2000 r/min within 5 s"));
    QVector<RecipeProblem> stepProblems = editor->check();
    ASSERT_EQ(stepProblems.size(), 2); // and the speed setting above
    EXPECT_TRUE(stepProblems.last().message.contains(QStringLiteral("olerance")))
        << qPrintable(stepProblems.last().message);
    steps->select(0);
    emit editor->problemsList()->itemActivated(editor->problemsList()->item(1));
    EXPECT_EQ(steps->table()->currentRow(), 3);
    tolerance = steps->detail()->findChild<QLineEdit*>(QStringLiteral("step_tolerance"));
    ASSERT_TRUE(tolerance);
    tolerance->selectAll();
    QTest::keyClicks(tolerance, QStringLiteral("50"));
    EXPECT_EQ(editor->check().size(), 1);
    // Start moved before communication priority: a DBU would refuse it, and the checker says so.
    steps->select(2);
    QPushButton* up = nullptr;
    for (auto* b : steps->findChildren<QPushButton*>())
        if (b->text() == QLatin1String("Move up"))
            up = b;
    ASSERT_TRUE(up);
    up->click();
    up->click();
    EXPECT_EQ(steps->table()->item(0, 1)->text(), QStringLiteral("Start"));
    EXPECT_EQ(editor->check().size(), 2);
    for (auto* b : steps->findChildren<QPushButton*>())
        if (b->text() == QLatin1String("Move down")) {
            b->click();
            b->click();
        }
    EXPECT_EQ(steps->table()->item(2, 1)->text(), QStringLiteral("Start"));
    EXPECT_EQ(editor->check().size(), 1);
    // A hold's limit is chosen from the family's live values, with the value's own unit.
    steps->select(4);
    auto* limits = steps->detail()->findChild<QTableWidget*>(QStringLiteral("stepLimits"));
    ASSERT_TRUE(limits);
    ASSERT_EQ(limits->rowCount(), 4);
    auto* parameter = qobject_cast<QComboBox*>(limits->cellWidget(3, 0));
    ASSERT_TRUE(parameter);
    EXPECT_EQ(parameter->currentData().toString(), QStringLiteral("status.load"));
    EXPECT_EQ(limits->item(3, 4)->text(), QStringLiteral("%"));
    parameter->setCurrentIndex(parameter->findData(QStringLiteral("status.current_speed")));
    EXPECT_EQ(limits->item(3, 4)->text(), QStringLiteral("r/min"));
    EXPECT_EQ(editor->check().size(), 1) << "a speed's max of 80 r/min is a valid limit";
    parameter->setCurrentIndex(parameter->findData(QStringLiteral("status.load")));
    EXPECT_EQ(limits->item(3, 4)->text(), QStringLiteral("%"));
    // A read step added after the hold asks for its value; removed, the steps are as they were.
    steps->addStep(QStringLiteral("read"));
    ASSERT_EQ(steps->table()->rowCount(), 9);
    EXPECT_EQ(steps->table()->item(5, 1)->text(), QStringLiteral("Read and compare"));
    EXPECT_EQ(steps->table()->item(5, 2)->text(), QStringLiteral("no value chosen to read yet"));
    stepProblems = editor->check();
    ASSERT_EQ(stepProblems.size(), 1); // the file cannot be read: the one problem
    EXPECT_TRUE(
        stepProblems.first().message.contains(QStringLiteral("steps[5] (read and compare)")))
        << qPrintable(stepProblems.first().message);
    for (auto* b : steps->findChildren<QPushButton*>())
        if (b->text() == QLatin1String("Remove"))
            b->click();
    ASSERT_EQ(steps->table()->rowCount(), 8);
    EXPECT_EQ(editor->check().size(), 1);
    steps->select(4);
    limits = steps->detail()->findChild<QTableWidget*>(QStringLiteral("stepLimits"));
    ASSERT_TRUE(limits);
    // A limit added without a value to measure is refused, naming the step and the limit (the
    // file cannot be read, so it is the one problem); removed, only the speed is left.
    QPushButton* addLimit = nullptr;
    QPushButton* removeLimit = nullptr;
    for (auto* b : steps->detail()->findChildren<QPushButton*>()) {
        if (b->text() == QLatin1String("Add limit"))
            addLimit = b;
        if (b->text() == QLatin1String("Remove limit"))
            removeLimit = b;
    }
    ASSERT_TRUE(addLimit && removeLimit);
    addLimit->click();
    EXPECT_EQ(steps->table()->item(4, 2)->text(), QStringLiteral("for 5 s; limits: 5"));
    stepProblems = editor->check();
    ASSERT_EQ(stepProblems.size(), 1);
    EXPECT_TRUE(stepProblems.first().message.contains(
        QStringLiteral("steps[4] (hold and measure) limits[4]: \"parameter\"")))
        << qPrintable(stepProblems.first().message);
    removeLimit->click(); // the new one is selected
    EXPECT_EQ(limits->rowCount(), 4);
    EXPECT_EQ(steps->table()->item(4, 2)->text(), QStringLiteral("for 5 s; limits: 4"));
    EXPECT_EQ(editor->check().size(), 1);

    // Fixed: saved, signed, and it loads as a recipe with the new value.
    settings->item(row, 2)->setText(QStringLiteral("1400"));
    ASSERT_TRUE(editor->saveTo(saved, &error)) << qPrintable(error);
    const std::optional<Recipe> recipe = RecipeFile::load(saved, &error);
    ASSERT_TRUE(recipe) << qPrintable(error);
    ASSERT_EQ(recipe->positions.first().steps.size(), 8);
    EXPECT_EQ(recipe->positions.first().steps[3].tolerance, 50);
    EXPECT_EQ(recipe->positions.first().steps[2].type, RecipeStep::Type::Start);
    EXPECT_EQ(recipe->positions.first().steps[4].limits[3].parameter,
              QStringLiteral("status.load"));
    bool found = false;
    for (const RecipeSetting& s : recipe->positions.first().settings)
        if (s.name == QLatin1String("spno2.speed")) {
            found = true;
            EXPECT_EQ(s.value.toDouble(), 1400);
        }
    EXPECT_TRUE(found);
    editor->close();
}

TEST_F(MainWindowEolToolsTest, ARecipeFromTheGoldenDriveOnTheBusPassesCheckAndSaves)
{
    window->findChild<EolMenu*>()->recipeEditorAction()->trigger();
    auto* editor = window->findChild<RecipeEditor*>();
    ASSERT_TRUE(editor);
    bool finished = false;
    bool ok = false;
    QString error;
    editor->newFromDrives({1, 150}, QStringLiteral("Twin belt"), QStringLiteral("A"),
                          [&](bool done, const QString& why) {
                              finished = true;
                              ok = done;
                              error = why;
                          });
    ASSERT_TRUE(waitFor([&] { return finished; }, 20000));
    ASSERT_TRUE(ok) << qPrintable(error);
    EXPECT_EQ(editor->positionChooser()->count(), 2);
    EXPECT_TRUE(editor->check().isEmpty());
    // A setting made per-unit leaves the settings, and gets its unit and the widest range the
    // drive allows (not across the DBU's gap between 0 and 250 r/min).
    QTableWidget* settings = editor->positionForm()->settingsTable();
    ASSERT_GE(settingRow(settings, QStringLiteral("spno3.speed")), 0);
    ASSERT_TRUE(editor->positionForm()->addUnitValue(QStringLiteral("spno3.speed")));
    EXPECT_EQ(settingRow(settings, QStringLiteral("spno3.speed")), -1);
    EXPECT_FALSE(editor->positionForm()->addSetting(QStringLiteral("spno3.speed")));
    EXPECT_FALSE(editor->positionForm()->addUnitValue(QStringLiteral("no.such")));
    QTemporaryDir dir;
    const QString saved = dir.filePath(QStringLiteral("twin.json"));
    for (const RecipeProblem& p : editor->check())
        ADD_FAILURE() << qPrintable(p.path + QStringLiteral(": ") + p.message);
    ASSERT_TRUE(editor->saveTo(saved, &error)) << qPrintable(error);
    const std::optional<Recipe> recipe = RecipeFile::load(saved, &error);
    ASSERT_TRUE(recipe) << qPrintable(error);
    ASSERT_EQ(recipe->positions.size(), 2);
    EXPECT_EQ(recipe->positions.at(1).machineNumber, 150);
    ASSERT_EQ(recipe->positions.first().unitValues.size(), 1);
    const RecipeUnitValue& perUnit = recipe->positions.first().unitValues.first();
    EXPECT_EQ(perUnit.unit, QStringLiteral("r/min"));
    EXPECT_EQ(perUnit.min, 250);
    EXPECT_EQ(perUnit.max, 3000);

    // Reading a drive that is not on the bus makes nothing.
    finished = false;
    editor->newFromDrives({33}, QStringLiteral("X"), QStringLiteral("1"),
                          [&](bool done, const QString& why) {
                              finished = true;
                              ok = done;
                              error = why;
                          });
    ASSERT_TRUE(finished);
    EXPECT_FALSE(ok);
    EXPECT_TRUE(error.contains(QStringLiteral("33"))) << qPrintable(error);
    editor->close();
}

// The editor's "Measure limits…" through the real window: the question names the drive and
// defaults to No (No runs nothing); Yes runs the golden drive once, the load limit comes down
// from the default 100 % to the measured load + margin, the description says so, and the
// motor is stopped afterwards.
TEST_F(MainWindowEolToolsTest, MeasuredLimitsFromTheGoldenDriveReplaceTheDefaultLoadLimit)
{
    window->findChild<EolMenu*>()->recipeEditorAction()->trigger();
    auto* editor = window->findChild<RecipeEditor*>();
    ASSERT_TRUE(editor);
    bool made = false;
    editor->newFromDrives({1}, QStringLiteral("Belt"), QStringLiteral("A"),
                          [&](bool ok, const QString& why) {
                              made = true;
                              EXPECT_TRUE(ok) << qPrintable(why);
                          });
    ASSERT_TRUE(waitFor([&] { return made; }, 20000));
    auto loadUpper = [editor] {
        QString error;
        const std::optional<Recipe> r = RecipeFile::fromEdited(editor->document(), &error);
        for (const RecipeStep& s : r ? r->positions.value(0).steps : QVector<RecipeStep>())
            for (const RecipeLimit& l : s.limits)
                if (l.parameter == QLatin1String("status.load"))
                    return l.upper.value_or(-1);
        return -1.0;
    };
    ASSERT_EQ(loadUpper(), 100);
    auto* measure = editor->findChild<GoldenMeasureButton*>(QStringLiteral("measureLimits"));
    ASSERT_TRUE(measure);
    QSignalSpy finished(measure, &GoldenMeasureButton::finished);
    auto question = [] {
        QMessageBox* box = nullptr;
        waitFor([&] {
            box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            return box != nullptr;
        });
        return box;
    };

    measure->click();
    QMessageBox* box = question();
    ASSERT_TRUE(box);
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("machine number 1")))
        << qPrintable(box->informativeText());
    EXPECT_EQ(box->defaultButton(), box->button(QMessageBox::No));
    box->button(QMessageBox::No)->click();
    QTest::qWait(300);
    EXPECT_FALSE(measure->isRunning());
    EXPECT_EQ(speedOf(1), 0);
    EXPECT_EQ(finished.count(), 0);

    measure->click();
    box = question();
    ASSERT_TRUE(box);
    box->button(QMessageBox::Yes)->click();
    // While the motor turns, a progress window with Stop is up.
    ASSERT_TRUE(waitFor([] {
        return qobject_cast<QProgressDialog*>(QApplication::activeModalWidget()) != nullptr;
    }));
    ASSERT_TRUE(waitFor([&] { return finished.count() == 1; }, 60000));
    EXPECT_TRUE(finished.at(0).at(1).toString().isEmpty())
        << qPrintable(finished.at(0).at(1).toString());
    const QStringList lines = finished.at(0).at(0).toStringList();
    EXPECT_FALSE(lines.isEmpty());
    const double upper = loadUpper();
    EXPECT_GT(upper, 0);
    EXPECT_LT(upper, 100);
    EXPECT_TRUE(editor->document()
                    .value(QStringLiteral("description"))
                    .toString()
                    .contains(QStringLiteral("measured on the golden unit")));
    EXPECT_TRUE(editor->check().isEmpty());
    EXPECT_EQ(speedOf(1), 0);
    if (auto* done = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
        done->close();

    // Esc while the motor turns: it is stopped, and the limits stay as they were.
    measure->click();
    box = question();
    ASSERT_TRUE(box);
    box->button(QMessageBox::Yes)->click();
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0; }, 20000));
    auto* progress = qobject_cast<QProgressDialog*>(QApplication::activeModalWidget());
    ASSERT_TRUE(progress);
    QTest::keyClick(progress, Qt::Key_Escape);
    ASSERT_TRUE(waitFor([&] { return finished.count() == 2; }, 20000));
    EXPECT_FALSE(finished.at(1).at(1).toString().isEmpty())
        << qPrintable(finished.at(1).at(0).toStringList().join(QLatin1Char(10)));
    EXPECT_EQ(speedOf(1), 0);
    EXPECT_EQ(loadUpper(), upper);
    if (auto* refused = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
        refused->close();
    editor->close();
}
