// People and recipes accountable in the real window (issue 25, item 5): on a station whose
// results database has users, an operator logs in as a badge scanner types
// ("name<Tab>password<Enter>"), cannot leave production mode or open a recipe, a recipe that is
// not approved does not run (the screen says why and who approves), and once an engineer
// approved it the unit runs and its record names the operator, the approval and the approver.
#include "model/access/AccessCheck.h"
#include "model/access/AuditTrail.h"
#include "model/access/RecipeApprovals.h"
#include "model/access/StationAccess.h"
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/station/EolStation.h"
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/eol/EolMenu.h"
#include "ui/eol/IdentityDialog.h"
#include "ui/eol/ProductionMode.h"
#include "ui/eol/ProductionView.h"
#include "ui/eol/RecipeApproveButton.h"
#include "ui/eol/RecipeEditor.h"
#include "ui/eol/StationActions.h"
#include "ui/eol/StationLogin.h"
#include "ui/workspace/DriveWorkspace.h"

#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

QString recipeFile(const QTemporaryDir& dir)
{
    QString error;
    std::optional<Recipe> recipe = RecipeFile::load(
        QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error);
    EXPECT_TRUE(recipe) << qPrintable(error);
    RecipePosition& p = recipe->positions[0];
    p.unitValues.clear();
    for (RecipeStep& s : p.steps)
        if (s.type == RecipeStep::Type::Hold)
            s.duration = 1;
    const QString path = dir.filePath(QStringLiteral("recipe.json"));
    EXPECT_TRUE(RecipeFile::save(*recipe, path, &error)) << qPrintable(error);
    return path;
}

StationUser person(const QString& name, const QString& display, Role role)
{
    StationUser u;
    u.name = name;
    u.displayName = display;
    u.role = role;
    return u;
}

// Types into whatever has the keyboard, as a scanner does.
void typeKeys(const QString& text)
{
    QWidget* focus = QApplication::focusWidget();
    ASSERT_TRUE(focus);
    QTest::keyClicks(focus, text);
}

void pressKey(Qt::Key key)
{
    QWidget* focus = QApplication::focusWidget();
    ASSERT_TRUE(focus);
    QTest::keyClick(focus, key);
}

// Answers the identity dialog that opens next as `user`; returns its message after the answer.
QString answerIdentity(MainWindow* window, const QString& user, const QString& password,
                       bool expectClosed)
{
    IdentityDialog* dialog = nullptr;
    // The one showing now (an earlier one, closed, may not be deleted yet).
    EXPECT_TRUE(waitFor([&] {
        for (IdentityDialog* d : window->findChildren<IdentityDialog*>())
            if (d->isVisible())
                dialog = d;
        return dialog != nullptr;
    }));
    if (!dialog)
        return QString();
    QPointer<IdentityDialog> alive(dialog);
    dialog->userField()->setText(user);
    dialog->passwordField()->setText(password);
    QTest::keyClick(dialog->passwordField(), Qt::Key_Return);
    if (expectClosed) {
        EXPECT_TRUE(waitFor([&] { return !alive || !alive->isVisible(); }));
        return QString();
    }
    EXPECT_TRUE(waitFor([&] { return alive && !alive->messageLabel()->text().isEmpty(); }));
    const QString message = alive ? alive->messageLabel()->text() : QString();
    if (alive)
        alive->reject();
    waitFor([&] { return !alive; }, 2000);
    return message;
}

// Closes the next message box once it shows; its text goes to *text.
void closeNextMessage(QString* text)
{
    auto* timer = new QTimer;
    QObject::connect(timer, &QTimer::timeout, [timer, text] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            *text = box->text();
            box->accept();
            timer->deleteLater();
        }
    });
    timer->start(20);
}

class MainWindowAccessTest : public MainWindowFixture
{
protected:
    // A results database with ada (administrator), olga (operator) and erik (engineer).
    static void addUsers(const QString& db)
    {
        QString error;
        auto database = ResultDatabase::open(db, &error);
        ASSERT_TRUE(database) << qPrintable(error);
        AccessCheck access(*database, QStringLiteral("setup"));
        ASSERT_TRUE(access.addUser(
            {}, person(QStringLiteral("ada"), QStringLiteral("Ada"), Role::Administrator),
            QStringLiteral("adm-pass"), &error));
        const Identity ada{QStringLiteral("ada"), QStringLiteral("adm-pass")};
        ASSERT_TRUE(access.addUser(
            ada, person(QStringLiteral("olga"), QStringLiteral("Olga O."), Role::Operator),
            QStringLiteral("op-pass"), &error));
        ASSERT_TRUE(access.addUser(
            ada, person(QStringLiteral("erik"), QStringLiteral("Erik E."), Role::Engineer),
            QStringLiteral("eng-pass"), &error));
    }
};

} // namespace

TEST_F(MainWindowAccessTest, AnOperatorLogsInRunsOnlyApprovedRecipesAndCannotLeaveOrOpen)
{
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("results.db"));
    addUsers(db);
    qputenv("OPENTOP_EOL_DB", db.toLocal8Bit());
    window->production()->toggleAction()->trigger();
    qunsetenv("OPENTOP_EOL_DB");
    ProductionMode* production = window->production();
    EolStation* station = production->station();
    ProductionView* view = production->view();
    ASSERT_TRUE(production->isActive());
    ASSERT_TRUE(waitFor([&] { return station->access()->isManaged(); }));
    StationLogin* login = view->login();
    EXPECT_TRUE(login->userField()->isVisible()) << "a managed station asks who works at it";
    EXPECT_FALSE(login->operatorField()->isVisible()) << "no free-text operator";
    EXPECT_FALSE(login->notice()->text().contains(QStringLiteral("No users set up")));

    ASSERT_TRUE(view->openRecipe(recipeFile(dir)));
    ASSERT_TRUE(waitFor([&] { return station->access()->approvalKnown(); }));
    EXPECT_TRUE(login->notice()->isVisible());
    EXPECT_TRUE(login->notice()->text().contains(QStringLiteral("is a draft")) &&
                login->notice()->text().contains(QStringLiteral("An engineer approves it")))
        << qPrintable(login->notice()->text());

    // A badge: name, Tab, password, Enter, into whatever has the keys.
    window->activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(window.get()));
    view->focusSerial(); // nobody logged in: the keys go to the login
    ASSERT_TRUE(waitFor([&] { return login->userField()->hasFocus(); }, 3000));
    typeKeys(QStringLiteral("olga"));
    pressKey(Qt::Key_Tab);
    EXPECT_TRUE(login->passwordField()->hasFocus());
    typeKeys(QStringLiteral("op-pass"));
    pressKey(Qt::Key_Return);
    ASSERT_TRUE(waitFor([&] { return station->access()->user().has_value(); }))
        << qPrintable(login->notice()->text());
    EXPECT_TRUE(login->userLabel()->text().contains(QStringLiteral("Olga O.")));
    EXPECT_TRUE(login->passwordField()->text().isEmpty()) << "never kept on the screen";

    // The draft does not run: said on the screen, nothing recorded.
    view->serialField()->setText(QStringLiteral("SN-D"));
    QTest::keyClick(view->serialField(), Qt::Key_Return);
    EXPECT_EQ(view->verdictLabel()->text(), QStringLiteral("NOT STARTED"));
    EXPECT_TRUE(view->reasonLabel()->text().contains(QStringLiteral("is a draft")))
        << qPrintable(view->reasonLabel()->text());

    // The operator may not leave production mode nor open another recipe.
    production->toggleAction()->trigger();
    const QString leave =
        answerIdentity(window.get(), QStringLiteral("olga"), QStringLiteral("op-pass"), false);
    EXPECT_TRUE(leave.contains(QStringLiteral("olga (operator) may not leave production mode")))
        << qPrintable(leave);
    EXPECT_TRUE(production->isActive());
    EXPECT_FALSE(window->workspace()->isVisible());
    QPushButton* open = nullptr;
    for (QPushButton* b : view->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("Open recipe…"))
            open = b;
    ASSERT_TRUE(open);
    open->click();
    const QString opening =
        answerIdentity(window.get(), QStringLiteral("olga"), QStringLiteral("op-pass"), false);
    EXPECT_TRUE(opening.contains(QStringLiteral("may not open or edit a recipe")))
        << qPrintable(opening);
    // A wrong password is refused as such.
    production->toggleAction()->trigger();
    EXPECT_TRUE(answerIdentity(window.get(), QStringLiteral("erik"), QStringLiteral("x"), false)
                    .contains(QStringLiteral("wrong user name or password")));
    EXPECT_TRUE(production->isActive());

    // An engineer approves this checksum (as the recipe editor's Approve… and `eol recipe
    // approve` do): the unit runs, its record names the operator, approval and approver.
    std::optional<AccessDecision> approval;
    station->access()->approve(Identity{QStringLiteral("erik"), QStringLiteral("eng-pass")},
                               station->recipe().product, station->recipe().revision,
                               station->recipeChecksum(), view,
                               [&](const AccessDecision& d) { approval = d; });
    ASSERT_TRUE(waitFor([&] { return approval.has_value(); }));
    ASSERT_TRUE(approval->allowed) << qPrintable(approval->message);
    EXPECT_FALSE(login->notice()->isVisible()) << qPrintable(login->notice()->text());
    view->serialField()->setText(QStringLiteral("SN-A"));
    QTest::keyClick(view->serialField(), Qt::Key_Return);
    ASSERT_TRUE(waitFor(
        [&] {
            const QString v = view->verdictLabel()->text();
            return v == QLatin1String("PASS") || v == QLatin1String("FAIL") ||
                   v == QLatin1String("NOT STARTED");
        },
        30000));
    EXPECT_EQ(view->verdictLabel()->text(), QStringLiteral("PASS"))
        << qPrintable(view->reasonLabel()->text());
    {
        QString error;
        auto database = ResultDatabase::open(db, &error);
        ASSERT_TRUE(database) << qPrintable(error);
        const auto draft = ResultQueries(*database).history(QStringLiteral("SN-D"), &error);
        ASSERT_TRUE(draft);
        EXPECT_TRUE(draft->isEmpty()) << "the draft ran nothing";
        const auto history = ResultQueries(*database).history(QStringLiteral("SN-A"), &error);
        ASSERT_TRUE(history && history->size() == 1) << qPrintable(error);
        EXPECT_EQ(history->first().operatorName, QStringLiteral("olga"));
        EXPECT_EQ(history->first().approver, QStringLiteral("erik"));
        EXPECT_FALSE(history->first().approvalId.isEmpty());
    }

    // An engineer leaves production mode; everything above is in the audit trail.
    production->toggleAction()->trigger();
    answerIdentity(window.get(), QStringLiteral("erik"), QStringLiteral("eng-pass"), true);
    ASSERT_TRUE(waitFor([&] { return !production->isActive(); }));
    EXPECT_TRUE(window->workspace()->isVisible());
    EXPECT_FALSE(station->access()->user()) << "leaving logs the operator out";
    QString all;
    EXPECT_TRUE(waitFor([&] {
        QString error;
        auto database = ResultDatabase::open(db, &error);
        const auto trail = database ? AuditTrail(*database).query({}, &error) : std::nullopt;
        if (!trail)
            return false;
        QStringList seen;
        for (const AuditEntry& e : *trail)
            seen << e.user + QLatin1Char(':') + e.action + QLatin1Char(':') + e.detail;
        all = seen.join(QLatin1Char('\n'));
        return all.contains(QStringLiteral("olga:login:")) &&
               all.contains(QStringLiteral("olga:refused:leave-production")) &&
               all.contains(QStringLiteral("olga:refused:edit-recipe")) &&
               all.contains(QStringLiteral(":login-failed:user \"erik\"")) &&
               all.contains(QStringLiteral("erik:recipe-approved")) &&
               all.contains(QStringLiteral("erik:privilege:leave-production")) &&
               all.contains(QStringLiteral("olga:logout"));
    })) << qPrintable(all);
}

TEST_F(MainWindowAccessTest, AStationWithoutUsersSaysSoInAmberAndWorksAsBefore)
{
    QTemporaryDir dir;
    qputenv("OPENTOP_EOL_DB", dir.filePath(QStringLiteral("results.db")).toLocal8Bit());
    window->production()->toggleAction()->trigger();
    qunsetenv("OPENTOP_EOL_DB");
    EolStation* station = window->production()->station();
    StationLogin* login = window->production()->view()->login();
    ASSERT_TRUE(
        waitFor([&] { return station->access()->state() == StationAccess::State::Unmanaged; }));
    EXPECT_TRUE(login->notice()->isVisible());
    EXPECT_EQ(login->notice()->text(),
              QStringLiteral("No users set up: anyone can run, edit and leave; set up users with "
                             "opentop-cli eol user add"));
    EXPECT_TRUE(login->notice()->styleSheet().contains(QStringLiteral("#ffe08a")));
    EXPECT_TRUE(login->operatorField()->isVisible());
    EXPECT_FALSE(login->userField()->isVisible());
    // Leaving needs nobody.
    window->production()->toggleAction()->trigger();
    EXPECT_FALSE(window->production()->isActive());
    EXPECT_FALSE(window->findChild<IdentityDialog*>());
}

TEST_F(MainWindowAccessTest, TheRecipeEditorAndItsApproveAskForAnEngineer)
{
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("results.db"));
    addUsers(db);
    qputenv("OPENTOP_EOL_DB", db.toLocal8Bit());
    window->production()->toggleAction()->trigger();
    qunsetenv("OPENTOP_EOL_DB");
    EolStation* station = window->production()->station();
    ASSERT_TRUE(waitFor([&] { return station->access()->isManaged(); }));
    window->production()->toggleAction()->trigger();
    answerIdentity(window.get(), QStringLiteral("erik"), QStringLiteral("eng-pass"), true);
    ASSERT_TRUE(waitFor([&] { return !window->production()->isActive(); }));

    // The editor: an operator is refused, an engineer gets it.
    QAction* editorAction = window->findChild<EolMenu*>()->recipeEditorAction();
    editorAction->trigger();
    EXPECT_TRUE(
        answerIdentity(window.get(), QStringLiteral("olga"), QStringLiteral("op-pass"), false)
            .contains(QStringLiteral("olga (operator) may not open or edit a recipe")));
    EXPECT_FALSE(window->findChild<RecipeEditor*>());
    editorAction->trigger();
    answerIdentity(window.get(), QStringLiteral("erik"), QStringLiteral("eng-pass"), true);
    RecipeEditor* editor = nullptr;
    ASSERT_TRUE(waitFor([&] { return (editor = window->findChild<RecipeEditor*>()) != nullptr; }));
    const QString path = recipeFile(dir);
    QString error;
    ASSERT_TRUE(editor->openFile(path, &error)) << qPrintable(error);

    // Approve…: an operator is refused; an engineer approves the saved file's checksum.
    auto* approve = editor->findChild<RecipeApproveButton*>();
    ASSERT_TRUE(approve);
    approve->click();
    EXPECT_TRUE(
        answerIdentity(window.get(), QStringLiteral("olga"), QStringLiteral("op-pass"), false)
            .contains(QStringLiteral("olga (operator) may not approve a recipe")));
    QString said;
    closeNextMessage(&said);
    approve->click();
    answerIdentity(window.get(), QStringLiteral("erik"), QStringLiteral("eng-pass"), true);
    ASSERT_TRUE(waitFor([&] { return !said.isEmpty(); }));
    EXPECT_TRUE(said.contains(QStringLiteral("is approved by erik"))) << qPrintable(said);
    QString checksum;
    ASSERT_TRUE(RecipeFile::load(path, &error, &checksum));
    auto database = ResultDatabase::open(db, &error);
    ASSERT_TRUE(database) << qPrintable(error);
    const auto approval = RecipeApprovals(*database).current(checksum, &error);
    ASSERT_TRUE(approval) << qPrintable(error);
    EXPECT_EQ(approval->approver, QStringLiteral("erik"));
}

// Issue 25 items 4 and 5 together: a passed serial scanned again waits for a technician; the
// logged-in operator is refused in the identity dialog, a technician allows it, and the override
// is in the audit trail with the retest's attempt number on its record.
TEST_F(MainWindowAccessTest, ARetestOfAPassedSerialAsksATechnicianNotTheOperator)
{
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("results.db"));
    addUsers(db);
    {
        QString error;
        auto database = ResultDatabase::open(db, &error);
        ASSERT_TRUE(database) << qPrintable(error);
        ASSERT_TRUE(AccessCheck(*database, QStringLiteral("setup"))
                        .addUser({QStringLiteral("ada"), QStringLiteral("adm-pass")},
                                 person(QStringLiteral("tess"), QStringLiteral("Tess T."),
                                        Role::Technician),
                                 QStringLiteral("tech-pass"), &error))
            << qPrintable(error);
    }
    qputenv("OPENTOP_EOL_DB", db.toLocal8Bit());
    window->production()->toggleAction()->trigger();
    qunsetenv("OPENTOP_EOL_DB");
    EolStation* station = window->production()->station();
    ProductionView* view = window->production()->view();
    ASSERT_TRUE(waitFor([&] { return station->access()->isManaged(); }));
    ASSERT_TRUE(view->openRecipe(recipeFile(dir)));
    std::optional<AccessDecision> approval;
    station->access()->approve(Identity{QStringLiteral("erik"), QStringLiteral("eng-pass")},
                               station->recipe().product, station->recipe().revision,
                               station->recipeChecksum(), view,
                               [&](const AccessDecision& d) { approval = d; });
    ASSERT_TRUE(waitFor([&] { return approval.has_value(); }));
    ASSERT_TRUE(approval->allowed) << qPrintable(approval->message);
    StationLogin* login = view->login();
    login->userField()->setText(QStringLiteral("olga"));
    login->passwordField()->setText(QStringLiteral("op-pass"));
    QTest::keyClick(login->passwordField(), Qt::Key_Return);
    ASSERT_TRUE(waitFor([&] { return station->access()->user().has_value(); }));

    const auto scan = [&](int rows) {
        view->serialField()->setText(QStringLiteral("SN-R"));
        QTest::keyClick(view->serialField(), Qt::Key_Return);
        return waitFor(
            [&] {
                return (view->unitsTable()->rowCount() > rows ||
                        view->verdictLabel()->text() == QLatin1String("NOT STARTED")) &&
                       !station->isRunning() && !station->isStarting();
            },
            30000);
    };
    ASSERT_TRUE(scan(0));
    ASSERT_EQ(view->verdictLabel()->text(), QStringLiteral("PASS"));
    ASSERT_TRUE(scan(1));
    EXPECT_EQ(view->verdictLabel()->text(), QStringLiteral("NOT STARTED"));
    QPushButton* retest = view->actions()->retestButton();
    ASSERT_TRUE(waitFor([&] { return retest->isVisible(); }));

    retest->click();
    const QString refused =
        answerIdentity(window.get(), QStringLiteral("olga"), QStringLiteral("op-pass"), false);
    EXPECT_TRUE(refused.contains(QStringLiteral("olga (operator) may not"))) << qPrintable(refused);
    EXPECT_EQ(view->unitsTable()->rowCount(), 1) << "nothing started for the operator";
    ASSERT_TRUE(retest->isVisible());
    retest->click();
    answerIdentity(window.get(), QStringLiteral("tess"), QStringLiteral("tech-pass"), true);
    ASSERT_TRUE(waitFor(
        [&] { return view->unitsTable()->rowCount() == 2 && !station->isRunning(); }, 30000));
    EXPECT_EQ(view->verdictLabel()->text(), QStringLiteral("PASS"))
        << qPrintable(view->reasonLabel()->text());
    QString error;
    auto database = ResultDatabase::open(db, &error);
    ASSERT_TRUE(database) << qPrintable(error);
    const auto history = ResultQueries(*database).history(QStringLiteral("SN-R"), &error);
    ASSERT_TRUE(history && history->size() == 2) << qPrintable(error);
    EXPECT_EQ(history->at(1).attempt, 2);
    EXPECT_EQ(history->at(1).operatorName, QStringLiteral("olga"));
    EXPECT_TRUE(waitFor([&] {
        const auto trail = AuditTrail(*database).query({}, &error);
        if (!trail)
            return false;
        bool override = false;
        for (const AuditEntry& e : *trail)
            override = override || (e.action == QLatin1String("retest-override") &&
                                    e.detail.contains(QStringLiteral("allowed by tess")));
        return override;
    })) << "the override is in the audit trail";
}
