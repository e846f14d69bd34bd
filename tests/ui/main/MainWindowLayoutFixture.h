// The layout tests' window: the program against the simulated bus of MainWindowFixture on a
// laptop's screen, and the walk that shows each page, dock and dialog and inspects it.
#pragma once

#include "tests/ui/main/LayoutInspector.h"
#include "tests/ui/main/MainWindowFixture.h"
#include "tests/ui/main/TsIndex.h"

#include <QAction>
#include <QDialog>
#include <QElapsedTimer>
#include <QMenuBar>
#include <QScreen>
#include <QStatusBar>
#include <QToolBar>

namespace opentop::test {

namespace layout {

inline void settle(int ms = 120)
{
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
}

inline std::string rect(const QRect& r)
{
    return QStringLiteral("%1,%2 %3×%4")
        .arg(r.x())
        .arg(r.y())
        .arg(r.width())
        .arg(r.height())
        .toStdString();
}

} // namespace layout

using layout::rect;
using layout::settle;

class MainWindowLayoutTest : public MainWindowFixture
{
protected:
    void SetUp() override
    {
        MainWindowFixture::SetUp();
        if (HasFatalFailure())
            return;
        screen = window->screen()->availableGeometry();
        window->setGeometry(QRect(screen.topLeft(), QSize(1366, 768)));
        settle();
    }

    // Records the problems of `top` under `where`.
    void inspect(QWidget* top, const QString& where)
    {
        // Layouts settle over a few passes (a row that wraps asks its parent for more height):
        // judged once they have, as the user sees them a moment later.
        for (int pass = 0; pass < 5; ++pass) {
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
            QCoreApplication::processEvents();
        }
        for (const QString& p : LayoutInspector::problems(top, screen))
            problems << QStringLiteral("[%1] %2").arg(where, p);
        // What a user must reach without scrolling: STOP ALL, the test run's commands, the
        // SPno selector, the way back to I/O priority, the drive's display.
        for (const QString& name : mustSee) {
            for (QWidget* w : top->findChildren<QWidget*>(name)) {
                if (!w->isVisibleTo(top) || w->window() != top)
                    continue;
                const QString hidden = LayoutInspector::outOfSight(w);
                if (!hidden.isEmpty())
                    problems << QStringLiteral("[%1] %2: %3")
                                    .arg(where, LayoutInspector::describe(w), hidden);
            }
        }
    }

    // What holds a window taller than the screen up: the central area (as tall as its tallest
    // page), the bars and the docks.
    void explainHeight()
    {
        if (window->height() <= screen.height())
            return;
        const QList<QDockWidget*> docks = window->findChildren<QDockWidget*>();
        // What holds the window up: the central area (as tall as its tallest page) and docks.
        problems << QStringLiteral("  bus panel needs %1 px, workspace %2 px, central %3 px")
                        .arg(window->busPanel()->minimumSizeHint().height())
                        .arg(window->workspace()->minimumSizeHint().height())
                        .arg(window->centralWidget()->minimumSizeHint().height());
        problems << QStringLiteral("  window needs %1 px, menu bar %2, status bar %3")
                        .arg(window->minimumSizeHint().height())
                        .arg(window->menuBar()->sizeHint().height())
                        .arg(window->statusBar()->minimumSizeHint().height());
        for (QToolBar* bar : window->findChildren<QToolBar*>())
            problems << QStringLiteral("  tool bar %1 needs %2 px")
                            .arg(bar->windowTitle())
                            .arg(bar->minimumSizeHint().height());
        for (QDockWidget* dock : docks)
            problems << QStringLiteral("  dock %1 needs %2 px")
                            .arg(dock->windowTitle())
                            .arg(dock->minimumSizeHint().height());
        QTabWidget* tabs = window->workspace()->tabs();
        for (int i = 0; i < tabs->count(); ++i)
            problems << QStringLiteral("  page %1 needs %2 px")
                            .arg(tabs->tabText(i))
                            .arg(tabs->widget(i)->minimumSizeHint().height());
    }

    // Object names of the widgets inspect() wants fully in sight.
    QStringList mustSee{QStringLiteral("stopAll"),
                        QStringLiteral("spno"),
                        QStringLiteral("switchPriority"),
                        QStringLiteral("ioPriority"),
                        QStringLiteral("start"),
                        QStringLiteral("stop"),
                        QStringLiteral("panelDigits"),
                        QStringLiteral("setSpeed"),
                        QStringLiteral("commutationsPerRevolution")};

    // The action a user finds by its text, in the window's language.
    QAction* action(const QString& text)
    {
        const QStringList wanted = translationsOf(language, text);
        for (QAction* a : window->findChildren<QAction*>()) {
            if (wanted.contains(plainMenuText(a->text())))
                return a;
        }
        ADD_FAILURE() << "no action " << qPrintable(text) << " ("
                      << qPrintable(wanted.join(QStringLiteral(", "))) << ")";
        return nullptr;
    }

    // Triggers `a`, which opens a modal dialog, inspects the dialog and closes it.
    void inspectModal(QAction* a, const QString& where)
    {
        ASSERT_NE(a, nullptr);
        bool seen = false;
        QTimer poll;
        poll.setInterval(30);
        QObject::connect(&poll, &QTimer::timeout, [&] {
            auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
            if (!dialog || !dialog->isVisible())
                return;
            poll.stop();
            settle();
            inspect(dialog, where);
            seen = true;
            dialog->reject();
        });
        poll.start();
        a->trigger();
        poll.stop();
        EXPECT_TRUE(seen) << qPrintable(where) << ": no dialog";
    }

    void inspectDialog(QDialog* dialog, const QString& where)
    {
        dialog->show();
        settle();
        inspect(dialog, where);
        dialog->close();
    }

    // Every tab of the selected drive's workspace, each in front in turn.
    void inspectPages(int slave, const QString& name)
    {
        select({slave});
        DeviceParameters* params = window->drives()->parameters(slave);
        ASSERT_NE(params, nullptr);
        ASSERT_TRUE(waitFor([&] { return window->workspace()->drive() == params; }));
        QTabWidget* tabs = window->workspace()->tabs();
        settle(300); // the values read and shown
        for (int i = 0; i < tabs->count(); ++i) {
            tabs->setCurrentIndex(i);
            settle();
            inspect(window.get(), QStringLiteral("%1, page %2").arg(name, tabs->tabText(i)));
        }
        tabs->setCurrentIndex(0);
    }

    QString report() const
    {
        return QStringLiteral("%1 layout problem(s):\n").arg(problems.size()) +
               problems.join(QLatin1Char('\n'));
    }

    // Every page, dock and dialog, inspected in turn.
    void inspectEverything();

    QRect screen;
    QStringList problems;
};

} // namespace opentop::test
