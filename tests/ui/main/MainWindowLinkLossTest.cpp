// A lost link one can come back from, and leaving that hands control back (issue 24, items 5
// and 6), through the real window on a serial line: opentop-sim as a process on a pty, killed
// mid-session and started again behind the same path. The link-lost message names the drive
// that was running; Ctrl+R comes back to the same port with the same drives and page; nothing
// is sent over the dead port; no window sits over a question; quitting stops each drive, reads
// the stop back and gives it back to its inputs (the simulator's registers read back).
#include "tests/e2e/SimProcess.h"
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/connection/ConnectionDialog.h"
#include "ui/main/LinkBar.h"
#include "ui/main/Reconnection.h"

#include <QComboBox>
#include <QProgressDialog>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QToolButton>

namespace opentop::test {

namespace {

QAction* actionNamed(MainWindow* window, const QString& text)
{
    for (QAction* a : window->findChildren<QAction*>())
        if (a->text() == text)
            return a;
    ADD_FAILURE() << "no action " << qPrintable(text);
    return nullptr;
}

// The windows on screen besides the main window: a question must be alone on top of it.
QStringList otherWindows(QWidget* window)
{
    QStringList shown;
    for (QWidget* w : QApplication::topLevelWidgets())
        if (w != window && w->isVisible() && w->isWindow() && !w->inherits("QMenu"))
            shown << QString::fromLatin1(w->metaObject()->className()) + QLatin1Char(':') +
                         w->objectName();
    return shown;
}

QString boxText(QMessageBox* box)
{
    QStringList buttons;
    for (QAbstractButton* b : box->buttons())
        buttons << b->text();
    return box->text() + QLatin1Char('\n') + box->informativeText() + QStringLiteral("\n[") +
           buttons.join(QStringLiteral("] [")) + QStringLiteral("] default: ") +
           (box->defaultButton() ? box->defaultButton()->text() : QString());
}

// Transmitted frames in the traffic log after `sequence`.
int sentAfter(TrafficLog* log, quint64 sequence)
{
    int sent = 0;
    for (const TrafficEntry& e : log->entriesAfter(sequence))
        sent += e.direction == TrafficEntry::Direction::Tx;
    return sent;
}

} // namespace

class MainWindowLinkLossTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QCoreApplication::setOrganizationName(QStringLiteral("OpenTOP-test"));
        QSettings().clear();
        QString error;
        ASSERT_TRUE(Language::install(QStringLiteral("en"), &error)) << qPrintable(error);
        registerBuiltInEditors();
        ASSERT_TRUE(dir.isValid());
        link = dir.filePath(QStringLiteral("ttyBUS"));
        startSimulator();
        window = std::make_unique<MainWindow>(
            [](const ConnectionSettings& s, TrafficLog* log, QString* e) {
                auto made = BackendFactory::makeClient(s, log);
                if (e)
                    *e = made.error;
                return std::move(made.client);
            });
        window->show();
        serial.kind = ConnectionSettings::Kind::Serial;
        serial.port = link;
        serial.baud = 19200;
        serial.parity = 'N';
        serial.stopBits = 1;
        serial.timeoutMs = 150;
        window->connectTo(serial, {{1, QStringLiteral("dbu200")},
                                   {2, QStringLiteral("dbu200")},
                                   {7, QStringLiteral("dcpid")}});
        ASSERT_TRUE(waitFor([&] { return window->isConnected() && present() == 3; }, 20000));
    }

    void TearDown() override
    {
        // Nothing may be left asking: a modal box would outlive the window it belongs to.
        for (QWidget* w : QApplication::topLevelWidgets())
            if (auto* box = qobject_cast<QMessageBox*>(w))
                box->close();
        window.reset();
        sim.reset();
        Language::uninstall();
    }

    void startSimulator()
    {
        sim = std::make_unique<SimProcess>();
        QString error;
        ASSERT_TRUE(
            sim->start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dbu200@2,dcpid@7"),
                        QStringLiteral("--pty"), link, QStringLiteral("--wire-timing"),
                        QStringLiteral("--half-duplex")},
                       &error))
            << qPrintable(error);
    }

    // The simulator dies as a process does: no goodbye on the line.
    void killSimulator()
    {
        sim->process().kill();
        ASSERT_TRUE(sim->process().waitForFinished(5000));
    }

    int present() const
    {
        int n = 0;
        if (BusDrives* drives = window->drives())
            for (int slave : drives->slaves())
                n += drives->info(slave).state == DeviceInfo::State::Present;
        return n;
    }

    // Starts a DBU as the Test run page does: communication priority, then start.
    void startDrive(int slave)
    {
        sim->command(QStringLiteral("set %1 0x100D 2").arg(slave));
        RunControl::Command start;
        start.action = RunControl::Action::Start;
        command(slave, start);
    }

    void command(int slave, const RunControl::Command& command)
    {
        RunControl control(window->client(), ProfileRegistry::builtIn());
        bool done = false;
        RunControl::Outcome outcome;
        control.execute(window->drives()->session(slave), command,
                        [&](const RunControl::Outcome& o) {
                            outcome = o;
                            done = true;
                        });
        ASSERT_TRUE(waitFor([&] { return done; }));
        ASSERT_TRUE(outcome.ok) << qPrintable(outcome.error);
    }

    // The status poller has read what the exit question and the lost link need to know.
    bool leftBehind(int slave, bool running)
    {
        for (int s : window->drives()->slaves())
            if (!window->statusPoller()->status(s).answered)
                return false; // a session in use has read every drive
        for (const DriveLeftBehind& d :
             ExitCheck::collect(*window->drives(), *window->statusPoller()))
            if (d.slave == slave && d.running == running)
                return true;
        return false;
    }

    QMessageBox* lostBox() const
    {
        auto* box = window->findChild<QMessageBox*>(QStringLiteral("connectionLostBox"));
        return box && box->isVisible() ? box : nullptr;
    }

    QTemporaryDir dir;
    QString link;
    ConnectionSettings serial;
    std::unique_ptr<SimProcess> sim;
    std::unique_ptr<MainWindow> window;
};

TEST_F(MainWindowLinkLossTest, TheLostLinkNamesTheRunningDriveAndCtrlRComesBackToTheSamePage)
{
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return leftBehind(1, true); }, 10000));
    window->busPanel()->view()->selectRow(window->busPanel()->model()->rowOf(1));
    QTabWidget* tabs = window->workspace()->tabs();
    ASSERT_TRUE(waitFor([&] { return tabs->count() > 3; }));
    int testRun = -1;
    for (int i = 0; i < tabs->count(); ++i)
        if (tabs->tabText(i) == QLatin1String("Test run"))
            testRun = i;
    ASSERT_GE(testRun, 0);
    tabs->setCurrentIndex(testRun);
    QAction* reconnect = window->reconnection()->action();
    QAction* reread = actionNamed(window.get(), QStringLiteral("&Re-read all"));
    EXPECT_FALSE(reconnect->isEnabled()); // connected: Ctrl+R re-reads
    EXPECT_TRUE(reread->isEnabled());
    EXPECT_EQ(reconnect->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_R));

    killSimulator();
    ASSERT_TRUE(waitFor([&] { return !window->isConnected() && lostBox(); }, 10000));
    const quint64 lostAt = window->trafficLog()->entries().isEmpty()
                               ? 0
                               : window->trafficLog()->entries().last().sequence;
    // The message names the drive that was running, with the age of what is known, and what
    // to check on the machine; Reconnect is its default.
    const QString message = boxText(lostBox());
    EXPECT_TRUE(message.contains(QStringLiteral("The connection to %1 was lost at").arg(link)))
        << qPrintable(message);
    EXPECT_TRUE(message.contains(QStringLiteral("Machine number 1 (DBU200-D): Running CW, in "
                                                "communication priority")))
        << qPrintable(message);
    EXPECT_TRUE(message.contains(QStringLiteral("when the link dropped"))) << qPrintable(message);
    EXPECT_TRUE(message.contains(QStringLiteral("STOP input"))) << qPrintable(message);
    EXPECT_FALSE(message.contains(QStringLiteral("Machine number 2"))) << qPrintable(message);
    EXPECT_TRUE(message.endsWith(QStringLiteral("default: Reconnect"))) << qPrintable(message);
    // So does the bar, which stays after the message is closed.
    LinkBar* bar = window->reconnection()->bar();
    EXPECT_TRUE(bar->isVisible());
    EXPECT_EQ(bar->look(), LinkBar::Look::Lost);
    EXPECT_TRUE(bar->text().contains(QStringLiteral("machine number 1 (DBU200-D)")))
        << qPrintable(bar->text());
    EXPECT_TRUE(bar->reconnectButton()->isVisible());
    EXPECT_TRUE(reconnect->isEnabled());
    EXPECT_FALSE(reread->isEnabled()); // one action per key at a time
    lostBox()->button(QMessageBox::Close)->click();

    // The machine is back (another simulator behind the same path), and drive 1 runs from its
    // own inputs meanwhile: the program must say so as soon as it has read it again.
    startSimulator();
    int runInput = 0;
    for (int mask : {1, 2, 4, 8}) {
        sim->command(QStringLiteral("input 1 %1").arg(mask));
        QTest::qWait(300);
        if (sim->get(1, 0x0109) > 0) {
            runInput = mask;
            break;
        }
        sim->command(QStringLiteral("input 1 0"));
    }
    ASSERT_NE(runInput, 0) << "no input runs drive 1";
    window->activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(window.get()));
    QTest::keyClick(window.get(), Qt::Key_R, Qt::ControlModifier);
    ASSERT_TRUE(waitFor([&] { return window->isConnected() && present() == 3; }, 20000))
        << qPrintable(window->connectionLabel()->text() + QLatin1Char('\n') + bar->text());
    EXPECT_EQ(window->client()->settings().port, link);
    EXPECT_EQ(window->drives()->slaves(), (QVector<int>{1, 2, 7}));
    EXPECT_EQ(window->drives()->info(1).model, QStringLiteral("DBU200-D"));
    ASSERT_TRUE(waitFor([&] { return window->busPanel()->selectedSlaves() == QVector<int>{1}; }));
    ASSERT_TRUE(waitFor([&] {
        return tabs->currentIndex() >= 0 &&
               tabs->tabText(tabs->currentIndex()) == QLatin1String("Test run");
    }));
    EXPECT_EQ(window->workspace()->drive(), window->drives()->parameters(1));
    ASSERT_TRUE(waitFor([&] { return bar->look() == LinkBar::Look::Attention; }, 15000))
        << qPrintable(bar->text());
    EXPECT_TRUE(bar->isVisible());
    EXPECT_TRUE(bar->text().contains(QStringLiteral("Machine number 1 (DBU200-D): Running")))
        << qPrintable(bar->text());
    EXPECT_FALSE(bar->text().contains(QStringLiteral("Machine number 2")))
        << qPrintable(bar->text());
    EXPECT_FALSE(reconnect->isEnabled());
    EXPECT_TRUE(reread->isEnabled());
    EXPECT_GT(sentAfter(window->trafficLog(), lostAt), 0); // the new link is used
}

TEST_F(MainWindowLinkLossTest, NothingIsSentOverTheDeadPortAndNoWindowSitsOverTheQuestion)
{
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return leftBehind(1, true); }, 10000));
    killSimulator();
    ASSERT_TRUE(waitFor([&] { return lostBox() != nullptr; }, 10000));
    const quint64 lostAt = window->trafficLog()->entries().last().sequence;
    lostBox()->button(QMessageBox::Close)->click();

    // The Connect dialog starts at the connection that was lost.
    QString port;
    QTimer::singleShot(200, [&] {
        auto* dialog = qobject_cast<ConnectionDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        port = dialog->findChild<QComboBox*>(QStringLiteral("port"))->currentText();
        dialog->reject();
    });
    actionNamed(window.get(), QStringLiteral("&Connect…"))->trigger();
    EXPECT_EQ(port, link);

    // Quitting asks about the drive as last known; no stop is offered, and no window is over
    // the question.
    QString question;
    QStringList others;
    QString modal; // the window on top when the question shows
    QObject::connect(
        window->reconnection(), &Reconnection::asking, window.get(),
        [&] {
            QWidget* top = QApplication::activeModalWidget();
            modal = top ? top->objectName() : QStringLiteral("none");
            others = otherWindows(window.get());
            auto* box = qobject_cast<QMessageBox*>(top);
            ASSERT_NE(box, nullptr);
            question = boxText(box);
            QTest::keyClick(box, Qt::Key_Escape); // stay
        },
        Qt::SingleShotConnection);
    EXPECT_FALSE(window->close());
    ASSERT_TRUE(waitFor([&] { return !question.isEmpty(); }));
    QTest::qWait(300);
    EXPECT_TRUE(window->isVisible());
    EXPECT_EQ(modal, QStringLiteral("linkLostExitQuestion"));
    EXPECT_EQ(others, QStringList{QStringLiteral("QMessageBox:linkLostExitQuestion")});
    EXPECT_TRUE(question.contains(
        QStringLiteral("Before you quit: the connection to %1 was lost").arg(link)))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("Machine number 1 (DBU200-D): Running CW")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("emergency stop"))) << qPrintable(question);
    EXPECT_FALSE(question.contains(QStringLiteral("[Stop"))) << qPrintable(question);
    EXPECT_TRUE(question.endsWith(QStringLiteral("default: Reconnect"))) << qPrintable(question);

    // Disconnect and connecting elsewhere ask the same; going on sends nothing.
    QObject::connect(
        window->reconnection(), &Reconnection::asking, window.get(),
        [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            ASSERT_NE(box, nullptr);
            for (QAbstractButton* b : box->buttons())
                if (b->text() == QLatin1String("Go on anyway"))
                    b->click();
        },
        Qt::SingleShotConnection);
    window->close();
    ASSERT_TRUE(waitFor([&] { return !window->isVisible(); }, 5000));
    EXPECT_EQ(sentAfter(window->trafficLog(), lostAt), 0)
        << "a request went out over the dead port";
}

TEST_F(MainWindowLinkLossTest, ConnectingToTheSamePortAfterTheLossComesBackWithoutAQuestion)
{
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return leftBehind(1, true); }, 10000));
    killSimulator();
    ASSERT_TRUE(waitFor([&] { return lostBox() != nullptr; }, 10000));
    lostBox()->button(QMessageBox::Close)->click();
    startSimulator();
    // Bus > Connect..., as it opens (at the lost connection), then Connect.
    bool asked = false;
    QObject::connect(window->reconnection(), &Reconnection::asking, window.get(),
                     [&] { asked = true; });
    QObject::connect(window->exitGuard(), &ExitGuard::asking, window.get(), [&] { asked = true; });
    QString port;
    QTimer::singleShot(200, [&] {
        auto* dialog = qobject_cast<ConnectionDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        port = dialog->findChild<QComboBox*>(QStringLiteral("port"))->currentText();
        dialog->accept();
    });
    actionNamed(window.get(), QStringLiteral("&Connect…"))->trigger();
    EXPECT_EQ(port, link);
    ASSERT_TRUE(waitFor([&] { return window->isConnected() && present() == 3; }, 20000))
        << qPrintable(window->connectionLabel()->text());
    EXPECT_FALSE(asked) << "nothing could be sent to the drives meanwhile: nothing to ask";
    EXPECT_EQ(window->drives()->slaves(), (QVector<int>{1, 2, 7}));
    // The new simulator's drives are stopped: once read again, nothing needs a look.
    LinkBar* bar = window->reconnection()->bar();
    EXPECT_TRUE(waitFor([&] { return !bar->isVisible(); }, 15000)) << qPrintable(bar->text());
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(
        QStringLiteral("Every drive read again: none is running")))
        << qPrintable(window->statusBar()->currentMessage());
}

TEST_F(MainWindowLinkLossTest, QuittingStopsEachDriveReadsItBackAndGivesControlBackToItsInputs)
{
    startDrive(1);
    sim->command(QStringLiteral("set 2 0x100D 2")); // left in communication priority, stopped
    RunControl::Command speed;                      // the DC controller runs on a set point
    speed.action = RunControl::Action::Speed;
    speed.speed = QStringLiteral("40");
    command(7, speed);
    ASSERT_TRUE(waitFor(
        [&] { return leftBehind(1, true) && leftBehind(2, false) && leftBehind(7, true); }, 10000));
    ASSERT_NE(sim->get(7, 0x0010), 0);
    QString question;
    QObject::connect(
        window->exitGuard(), &ExitGuard::asking, window.get(),
        [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            ASSERT_NE(box, nullptr);
            question = boxText(box);
            QTest::keyClick(box, Qt::Key_Return);
        },
        Qt::SingleShotConnection);
    EXPECT_FALSE(window->close());
    ASSERT_TRUE(waitFor([&] { return !window->isVisible(); }, 30000)) << qPrintable(question);
    // Every drive named with what happens to it; the default does all of it.
    EXPECT_TRUE(question.contains(
        QStringLiteral("Machine number 1 (DBU200-D): Running CW, in communication priority")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("→ stopped (confirmed by reading it), then given "
                                                 "back to its own inputs (I/O priority, read "
                                                 "back)")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("Machine number 2 (DBU200-D): in communication "
                                                 "priority")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("→ given back to its own inputs (I/O priority, "
                                                 "read back)")))
        << qPrintable(question);
    const qsizetype dc = question.indexOf(QStringLiteral("Machine number 7"));
    ASSERT_GE(dc, 0) << qPrintable(question);
    EXPECT_TRUE(question.mid(dc).contains(QStringLiteral("→ stopped (confirmed by reading it); its "
                                                         "family has no I/O priority setting")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("[Give control back only]")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("[Leave them running]"))) << qPrintable(question);
    EXPECT_TRUE(question.endsWith(QStringLiteral("default: Stop and give control back")))
        << qPrintable(question);
    // The simulator's registers: stopped, and the machine's own inputs in charge again.
    EXPECT_EQ(sim->get(1, 0x0109), 0);
    EXPECT_EQ(sim->get(1, 0x100D), 1);
    EXPECT_EQ(sim->get(2, 0x100D), 1);
    EXPECT_EQ(sim->get(7, 0x0010), 0); // no output: stopped
}

TEST_F(MainWindowLinkLossTest, AStopThatFailsIsReportedWithNoProgressWindowOverTheReport)
{
    startDrive(1);
    sim->command(QStringLiteral("ignore-stop 1 on"));
    ASSERT_TRUE(waitFor([&] { return leftBehind(1, true); }, 10000));
    QString report;
    QStringList others;
    QString modal;
    QObject::connect(
        window->exitGuard(), &ExitGuard::asking, window.get(),
        [&] {
            QTest::keyClick(QApplication::activeModalWidget(), Qt::Key_Return); // the default
            QObject::connect(
                window->exitGuard(), &ExitGuard::asking, window.get(),
                [&] {
                    // Looked at as a person would, a while after it came: nothing may have
                    // come over it meanwhile (a progress window's own timer, say).
                    QTimer::singleShot(4500, window.get(), [&] {
                        QWidget* top = QApplication::activeModalWidget();
                        modal = top ? top->objectName() : QStringLiteral("none");
                        others = otherWindows(window.get());
                        auto* box = qobject_cast<QMessageBox*>(top);
                        ASSERT_NE(box, nullptr);
                        report = boxText(box);
                        QTest::keyClick(box, Qt::Key_Escape); // stay connected
                    });
                },
                Qt::SingleShotConnection);
        },
        Qt::SingleShotConnection);
    window->close();
    ASSERT_TRUE(waitFor([&] { return !report.isEmpty(); }, 60000));
    EXPECT_EQ(modal, QStringLiteral("exitFailures"));
    EXPECT_EQ(others, QStringList{QStringLiteral("QMessageBox:exitFailures")});
    EXPECT_TRUE(window->findChildren<QProgressDialog*>().isEmpty());
    EXPECT_TRUE(report.contains(QStringLiteral("Machine number 1: STILL RUNNING")))
        << qPrintable(report);
    EXPECT_TRUE(report.contains(QStringLiteral("Machine number 1: left in communication priority")))
        << qPrintable(report);
    QTest::qWait(200);
    EXPECT_TRUE(window->isVisible());
    EXPECT_EQ(sim->get(1, 0x100D), 2); // not handed to its inputs while it runs
}

} // namespace opentop::test
