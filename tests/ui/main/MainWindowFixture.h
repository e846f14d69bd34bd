// The whole program's window against an in-process simulated bus (dbu200@1, dbu200@2,
// dbu400@150, dcpid@7), connected and identified; helpers that act as the user or the drive.
#pragma once
#include "connection/BackendFactory.h"
#include "model/bus/BusDrives.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/i18n/Language.h"
#include "model/monitor/MonitorHub.h"
#include "model/profile/ProfileRegistry.h"
#include "model/run/ExitCheck.h"
#include "model/run/RunControl.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "sim/SimBus.h"
#include "transport/ModbusClient.h"
#include "transport/TrafficLog.h"
#include "ui/bus/BusListModel.h"
#include "ui/bus/BusOverview.h"
#include "ui/bus/BusOverviewModel.h"
#include "ui/bus/BusPanel.h"
#include "ui/main/MainWindow.h"
#include "ui/monitor/MonitorPage.h"
#include "ui/pages/EditorRegistry.h"
#include "ui/run/ExitGuard.h"
#include "ui/run/StopAllButton.h"
#include "ui/run/TestRunPanel.h"
#include "ui/workspace/DriveWorkspace.h"
#include "ui/workspace/ParameterField.h"
#include "ui/workspace/ParameterPage.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDockWidget>
#include <QItemSelectionModel>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTabWidget>
#include <QTableView>
#include <QTest>
#include <QTime>
#include <QTimer>
#include <gtest/gtest.h>

namespace opentop::test {

using namespace opentop;

inline bool waitFor(const std::function<bool()>& condition, int ms = 10000)
{
    QDeadlineTimer deadline(ms);
    while (!condition() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return condition();
}

// The drive's Test run page, made current (so that it is visible and watches its drive).
inline TestRunPanel* showTestRun(MainWindow& window, int slave)
{
    QTabWidget* tabs = window.workspace()->tabs();
    TestRunPanel* panel = nullptr;
    int tab = -1;
    waitFor([&] {
        for (TestRunPanel* p : window.findChildren<TestRunPanel*>()) {
            for (int i = 0; i < tabs->count(); ++i) {
                if (p->slave() == slave && tabs->widget(i)->isAncestorOf(p)) {
                    panel = p;
                    tab = i;
                }
            }
        }
        return panel != nullptr;
    });
    if (panel)
        tabs->setCurrentIndex(tab);
    return panel;
}

// Clicks `name` on the page and answers the start question with Yes; returns its text.
inline QString clickAndConfirm(TestRunPanel* panel, const QString& name)
{
    panel->findChild<QPushButton*>(name)->click();
    QMessageBox* box = nullptr;
    waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box != nullptr;
    });
    if (!box)
        return QString();
    const QString text = box->text();
    box->button(QMessageBox::Yes)->click();
    return text;
}

class MainWindowFixture : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QCoreApplication::setOrganizationName(QStringLiteral("OpenTOP-test"));
        QSettings().clear();
        // One shift that began 6 h ago: a test near 06:00, 14:00 or 22:00 never sees the
        // station's figures start a new shift under it.
        QSettings().setValue(
            QStringLiteral("eol/shifts"),
            QTime::currentTime().addSecs(-6 * 3600).toString(QStringLiteral("HH:mm")));
        {
            // As opentop does (English too: its plural forms): before the window makes any text.
            QString error;
            ASSERT_TRUE(Language::install(language, &error)) << qPrintable(error);
        }
        registerBuiltInEditors();
        window = std::make_unique<MainWindow>(
            [this](const ConnectionSettings& s, TrafficLog* log, QString* error) {
                return makeClient(s, log, error);
            });
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.simSpec = QStringLiteral("dbu200@1,dbu200@2,dbu400@150,dcpid@7");
        settings.timeoutMs = 100;
        window->show();
        window->connectTo(settings, {{1, QStringLiteral("dbu200")},
                                     {2, QStringLiteral("dbu200")},
                                     {150, QStringLiteral("dbu400")},
                                     {7, QStringLiteral("dcpid")}});
        ASSERT_TRUE(
            waitFor([this] { return window->drives() && window->drives()->slaves().size() == 4; }));
    }

    // The client the window connects with (sets `bus`); a derived fixture may give the line
    // wire timing.
    virtual std::unique_ptr<ModbusClient> makeClient(const ConnectionSettings& s, TrafficLog* log,
                                                     QString* error)
    {
        auto made = BackendFactory::makeClient(s, log);
        bus = made.simBus;
        if (error)
            *error = made.error;
        return std::move(made.client);
    }

    int simRegister(int slave, quint16 address)
    {
        const QString text =
            bus->control(slave, {QStringLiteral("get"), QString::number(address)}).text;
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("= (\\d+) ")).match(text);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }

    void select(const QVector<int>& slaves)
    {
        QTableView* view = window->busPanel()->view();
        view->clearSelection();
        for (int slave : slaves) {
            const int row = window->busPanel()->model()->rowOf(slave);
            view->selectionModel()->select(view->model()->index(row, 0),
                                           QItemSelectionModel::Select | QItemSelectionModel::Rows);
        }
    }

    // Starts a DBU the way the Test run page does: communication priority, then start.
    void startDrive(int slave)
    {
        bus->control(slave, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
        RunControl control(window->client(), ProfileRegistry::builtIn());
        RunControl::Command start;
        start.action = RunControl::Action::Start;
        bool done = false;
        RunControl::Outcome outcome;
        control.execute(window->drives()->session(slave), start, [&](const RunControl::Outcome& o) {
            outcome = o;
            done = true;
        });
        ASSERT_TRUE(waitFor([&] { return done; }));
        ASSERT_TRUE(outcome.ok) << qPrintable(outcome.error);
    }
    int speedOf(int slave) { return simRegister(slave, 0x0109); }

    // Answers the exit question with `key` (Return: the default button, Escape: Cancel) once it
    // shows, and returns its text.
    std::shared_ptr<QString> answerExitQuestion(Qt::Key key)
    {
        auto text = std::make_shared<QString>();
        QObject::connect(
            window->exitGuard(), &ExitGuard::asking, window.get(),
            [text, key] {
                auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                ASSERT_NE(box, nullptr);
                *text = box->text() + QLatin1Char('\n') + box->informativeText() +
                        QLatin1Char('\n') + box->defaultButton()->text();
                QTest::keyClick(box, key);
            },
            Qt::SingleShotConnection);
        return text;
    }
    // The status poller has seen what the exit check needs to know.
    bool leftBehind(int slave)
    {
        for (const DriveLeftBehind& d :
             ExitCheck::collect(*window->drives(), *window->statusPoller())) {
            if (d.slave == slave)
                return true;
        }
        return false;
    }

    void TearDown() override
    {
        window.reset();
        Language::uninstall();
    }

    QString language = QStringLiteral("en"); // set by a derived fixture before SetUp
    std::shared_ptr<SimBus> bus;
    std::unique_ptr<MainWindow> window;
};

} // namespace opentop::test
