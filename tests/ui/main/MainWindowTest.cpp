// The whole window against an in-process simulated bus: connect, the configured drives are
// identified with their variants, selecting one opens its pages, an edit written from the
// workspace reaches the drive, several drives of one family enable the multi-drive write.
#include "tests/ui/main/MainWindowFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {
using MainWindowTest = MainWindowFixture;
} // namespace

TEST_F(MainWindowTest, ConfiguredDrivesAreIdentifiedWithTheirVariants)
{
    BusDrives* drives = window->drives();
    EXPECT_TRUE(window->isConnected());
    EXPECT_EQ(drives->info(1).model, QStringLiteral("DBU200-D"));
    EXPECT_EQ(drives->info(150).model, QStringLiteral("DBU400-D4"));
    EXPECT_EQ(drives->info(7).family, QStringLiteral("dcpid"));
    BusListModel* model = window->busPanel()->model();
    const int row = model->rowOf(150);
    ASSERT_GE(row, 0);
    EXPECT_EQ(model->index(row, BusListModel::Switches).data().toString(),
              QStringLiteral("SW1=9 SW2=6"));
}

TEST_F(MainWindowTest, SelectingADriveOpensItsPagesAndAnEditReachesTheDrive)
{
    select({1});
    DriveWorkspace* workspace = window->workspace();
    ASSERT_TRUE(waitFor([&] { return workspace->drive() != nullptr; }));
    QStringList titles;
    for (int i = 0; i < workspace->tabs()->count(); ++i)
        titles << workspace->tabs()->tabText(i).remove(QLatin1Char('&'));
    for (const char* expected :
         {"Running data", "Core parameters", "Speed display", "Test run", "Alarms"})
        EXPECT_TRUE(
            std::any_of(titles.begin(), titles.end(),
                        [&](const QString& t) { return t.contains(QString::fromUtf8(expected)); }))
            << expected << " not in " << titles.join(QStringLiteral(", ")).toStdString();
    DeviceParameters* params = window->drives()->parameters(1);
    ASSERT_TRUE(
        waitFor([&] { return params->entry(QStringLiteral("spno2.speed"))->device.valid; }));
    auto* field = workspace->findChild<ParameterField*>(QString(), Qt::FindChildrenRecursively);
    ASSERT_NE(field, nullptr);
    const QList<ParameterField*> fields = workspace->findChildren<ParameterField*>();
    ParameterField* speed = nullptr;
    for (ParameterField* f : fields)
        speed = f->parameterName() == QLatin1String("spno2.speed") ? f : speed;
    ASSERT_NE(speed, nullptr);
    speed->enter(QStringLiteral("2200"));
    EXPECT_TRUE(params->hasPending());
    workspace->writeAll();
    ASSERT_TRUE(waitFor([&] { return !params->hasPending(); }));
    EXPECT_EQ(simRegister(1, 0xCA03), 2200);
}

TEST_F(MainWindowTest, SeveralDrivesOfOneFamilyEnableTheMultiDriveWrite)
{
    QAction* multi = nullptr;
    for (QAction* a : window->findChildren<QAction*>())
        multi = a->text().contains(QStringLiteral("selected drives")) ? a : multi;
    ASSERT_NE(multi, nullptr);
    select({1, 2});
    ASSERT_TRUE(waitFor([&] { return multi->isEnabled(); }));
    select({1, 7}); // a DBU and a DC controller have no setting in common
    ASSERT_TRUE(waitFor([&] { return !multi->isEnabled(); }));
}

TEST_F(MainWindowTest, StopAllIsOnTheToolbarAndFramesReachTheTrafficLog)
{
    ASSERT_NE(window->stopAllButton(), nullptr);
    EXPECT_TRUE(window->stopAllButton()->isVisibleTo(window.get()));
    // Once the drives are known, their frames (the status poll) carry parameter names.
    EXPECT_TRUE(waitFor([&] {
        for (const TrafficEntry& e : window->trafficLog()->entries()) {
            if (e.summary.contains(QStringLiteral("core.control_priority")))
                return true;
        }
        return false;
    }));
}

TEST_F(MainWindowTest, ADrivesMonitorComesFirstAndTheBusViewsPollOnlyWhileShown)
{
    select({2});
    DriveWorkspace* workspace = window->workspace();
    ASSERT_TRUE(waitFor([&] { return workspace->drive() != nullptr; }));
    auto* monitor = qobject_cast<MonitorPage*>(workspace->tabs()->currentWidget());
    ASSERT_NE(monitor, nullptr);
    EXPECT_EQ(workspace->tabs()->indexOf(monitor), 0);
    // Only the drive shown is polled (the page of the one selected before has gone).
    EXPECT_TRUE(waitFor([&] { return window->monitorHub()->watched() == QVector<int>{2}; }))
        << window->monitorHub()->watched().size();
    ASSERT_TRUE(waitFor([&] { return monitor->samplesShown() > 0; }));
    // The overview and the trends watch every drive while shown, and none once closed.
    window->monitorAll();
    EXPECT_EQ(window->monitorHub()->watched(), (QVector<int>{1, 2, 7, 150}));
    ASSERT_TRUE(waitFor([&] { return window->monitorHub()->latest(150).has_value(); }));
    EXPECT_EQ(window->busOverview()->model()->rowCount(), 4);
    for (QDockWidget* dock : window->findChildren<QDockWidget*>())
        dock->hide();
    EXPECT_EQ(window->monitorHub()->watched(), QVector<int>{2});
    // Another page of the drive in front: its monitor stops polling.
    workspace->tabs()->setCurrentIndex(1);
    EXPECT_TRUE(window->monitorHub()->watched().isEmpty());
    // Another connection: the views of the old bus go with it, new ones watch the new bus.
    ConnectionSettings other;
    other.kind = ConnectionSettings::Kind::Simulated;
    other.simSpec = QStringLiteral("dcpid@9");
    window->connectTo(other, {{9, QStringLiteral("dcpid")}});
    ASSERT_TRUE(waitFor([&] { return window->drives()->slaves() == QVector<int>{9}; }));
    // The drive that answered first is selected and its monitor shown: only it is polled.
    EXPECT_TRUE(waitFor([&] { return window->monitorHub()->watched() == QVector<int>{9}; }));
    window->monitorAll();
    EXPECT_EQ(window->monitorHub()->watched(), QVector<int>{9});
    EXPECT_TRUE(waitFor([&] { return window->monitorHub()->latest(9).has_value(); }));
}

TEST_F(MainWindowTest, PauseAndCtrlShiftSStopEveryDriveFromTheWindowAndFromAModalDialog)
{
    startDrive(1);
    startDrive(2);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0 && speedOf(2) > 0; }));

    // Pause, pressed wherever the focus is in the main window.
    window->activateWindow();
    QWidget* focus = QApplication::focusWidget() ? QApplication::focusWidget() : window.get();
    QTest::keyClick(focus, Qt::Key_Pause);
    EXPECT_TRUE(waitFor([&] { return speedOf(1) == 0 && speedOf(2) == 0; }, 15000))
        << "speeds " << speedOf(1) << ", " << speedOf(2);

    // Ctrl+Shift+S while a modal dialog blocks the window (a QShortcut would not fire here).
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0; }));
    bool pressed = false;
    QTimer::singleShot(100, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        ASSERT_NE(modal, nullptr);
        QTest::keyClick(modal, Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
        pressed = true;
        QTimer::singleShot(0, modal, &QWidget::close);
    });
    QMessageBox::information(window.get(), QStringLiteral("modal"), QStringLiteral("a dialog"));
    EXPECT_TRUE(pressed);
    EXPECT_TRUE(waitFor([&] { return speedOf(1) == 0; }, 15000)) << "speed " << speedOf(1);
}

TEST_F(MainWindowTest, QuittingWithARunningDriveNamesItStopsItAndGivesItBackByDefault)
{
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0 && leftBehind(1); }));
    auto question = answerExitQuestion(Qt::Key_Return);
    EXPECT_FALSE(window->close()); // not yet: the question comes first
    ASSERT_TRUE(waitFor([&] { return !window->isVisible(); }, 20000)) << qPrintable(*question);
    EXPECT_TRUE(question->contains(QStringLiteral("Machine number 1 (DBU200-D): Running CW")))
        << qPrintable(*question);
    EXPECT_TRUE(question->contains(QStringLiteral("communication priority")));
    EXPECT_TRUE(question->endsWith(QStringLiteral("Stop and give control back")))
        << qPrintable(*question);
    EXPECT_EQ(speedOf(1), 0);             // stopped before the window closed
    EXPECT_EQ(simRegister(1, 0x100D), 1); // and its own inputs in charge again
}

TEST_F(MainWindowTest, DisconnectingWithARunningDriveNamesItAndStopsItFirst)
{
    // Bus > Disconnect, as a user finds it in the menu.
    QAction* disconnect = nullptr;
    for (QAction* a : window->findChildren<QAction*>()) {
        if (a->text().remove(QLatin1Char('&')) == QStringLiteral("Disconnect"))
            disconnect = a;
    }
    ASSERT_NE(disconnect, nullptr);
    EXPECT_TRUE(disconnect->isEnabled());
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0 && leftBehind(1); }));
    auto question = answerExitQuestion(Qt::Key_Return);
    disconnect->trigger();
    ASSERT_TRUE(waitFor([&] { return !window->isConnected(); }, 20000)) << qPrintable(*question);
    EXPECT_TRUE(question->contains(QStringLiteral("Machine number 1 (DBU200-D): Running CW")))
        << qPrintable(*question);
    EXPECT_EQ(speedOf(1), 0); // stopped before the connection closed
    EXPECT_FALSE(disconnect->isEnabled());
    EXPECT_TRUE(window->isVisible());
    EXPECT_TRUE(window->connectionLabel()->text().contains(QStringLiteral("Not connected")));
}

TEST_F(MainWindowTest, CancellingTheExitQuestionKeepsTheWindowAndTheDriveRunning)
{
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0 && leftBehind(1); }));
    auto question = answerExitQuestion(Qt::Key_Escape);
    window->close();
    ASSERT_TRUE(waitFor([&] { return !question->isEmpty(); }));
    QTest::qWait(300);
    EXPECT_TRUE(window->isVisible());
    EXPECT_GT(speedOf(1), 0);
}

TEST_F(MainWindowTest, ADriveLeftInCommunicationPriorityIsGivenBackToItsInputs)
{
    bus->control(2, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    ASSERT_TRUE(waitFor([&] { return leftBehind(2); }));
    auto question = answerExitQuestion(Qt::Key_Return); // not running: the default gives back
    window->close();
    ASSERT_TRUE(waitFor([&] { return !window->isVisible(); }, 20000)) << qPrintable(*question);
    EXPECT_TRUE(question->contains(QStringLiteral("Machine number 2")));
    EXPECT_FALSE(question->contains(QStringLiteral("Machine number 1")));
    EXPECT_TRUE(question->endsWith(QStringLiteral("Give control back (I/O priority)")));
    EXPECT_EQ(simRegister(2, 0x100D), 1); // I/O priority, written and verified
}

TEST_F(MainWindowTest, AStartConfirmationDoesNotSurviveAReconnection)
{
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    select({1});
    TestRunPanel* panel = nullptr;
    ASSERT_TRUE(waitFor([&] {
        panel = window->findChild<TestRunPanel*>();
        return panel && panel->commandsEnabled();
    }));
    panel->findChild<QPushButton*>(QStringLiteral("start"))->click();
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box != nullptr;
    }));
    box->button(QMessageBox::Yes)->click();
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0; }));
    EXPECT_TRUE(TestRunPanel::startConfirmed(1));

    // Another connection may be another machine with the same numbers: ask again.
    ConnectionSettings again;
    again.kind = ConnectionSettings::Kind::Simulated;
    again.simSpec = QStringLiteral("dbu200@1");
    again.timeoutMs = 100;
    window->connectTo(again, {{1, QStringLiteral("dbu200")}});
    EXPECT_FALSE(TestRunPanel::startConfirmed(1));
}

TEST_F(MainWindowTest, TheCoreParametersPageCannotWriteAModeThatInvalidatesTheInputFunctions)
{
    select({1});
    DriveWorkspace* workspace = window->workspace();
    DeviceParameters* params = window->drives()->parameters(1);
    ASSERT_TRUE(waitFor([&] { return workspace->drive() == params; }));
    ASSERT_TRUE(
        waitFor([&] { return params->entry(QStringLiteral("core.control_mode"))->device.valid; }));
    // The generic Core parameters page among the drive's tabs (the I/O terminals page has a mode
    // field and a guard of its own; pages of a drive shown before may still await deletion).
    ParameterField* mode = nullptr;
    ParameterPage* page = nullptr;
    for (int i = 0; i < workspace->tabs()->count() && !mode; ++i) {
        auto* tab = qobject_cast<ParameterPage*>(workspace->tabs()->widget(i));
        if (!tab || tab->inherits("opentop::IoTerminalsPage"))
            continue;
        for (ParameterField* f : tab->findChildren<ParameterField*>()) {
            if (f->parameterName() == QLatin1String("core.control_mode")) {
                mode = f;
                page = tab;
            }
        }
    }
    ASSERT_NE(mode, nullptr);
    mode->enter(QStringLiteral("Mode1"));
    ASSERT_TRUE(params->hasPending());
    const int modeBefore = simRegister(1, 0x2015);
    page->writePage(); // the page's own write, which no other page's guard holds back
    ASSERT_TRUE(waitFor([&] {
        return params->entry(QStringLiteral("core.control_mode"))->state ==
               DeviceParameters::State::Failed;
    }));
    EXPECT_EQ(simRegister(1, 0x2015), modeBefore);
    EXPECT_TRUE(params->entry(QStringLiteral("core.control_mode"))
                    ->message.contains(QStringLiteral("Input X0 function")));
}

TEST_F(MainWindowTest, ALostConnectionIsRedInTheStatusBarAndALongReasonDoesNotWidenTheWindow)
{
    window->resize(1366, 768);
    const QString reason =
        QStringLiteral("Cannot open /dev/ttyUSB0 19200 8N1: Input/output error: ") +
        QString(3000, QLatin1Char('x')) + QStringLiteral("\nsecond line");
    // The explanation comes in a modal window; close it as a person would.
    QTimer::singleShot(200, [] {
        if (QWidget* modal = QApplication::activeModalWidget())
            modal->close();
    });
    emit window->client()->connectionLost(reason);
    QLabel* label = window->connectionLabel();
    EXPECT_TRUE(label->text().startsWith(QStringLiteral("Connection lost: Cannot open")))
        << qPrintable(label->text());
    EXPECT_FALSE(label->text().contains(QStringLiteral("second line")));
    EXPECT_EQ(label->toolTip(), QStringLiteral("Connection lost: ") + reason);
    EXPECT_TRUE(label->styleSheet().contains(QStringLiteral("#b01c1c")));
    EXPECT_LE(window->minimumSizeHint().width(), 1366);
    EXPECT_LE(label->sizeHint().width(), 600);
}
