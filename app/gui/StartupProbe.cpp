#include "app/gui/StartupProbe.h"

#include "model/bus/BusDrives.h"
#include "ui/main/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QEvent>
#include <QTimer>
#include <cstdio>

namespace opentop {

namespace {

const QString kStartupProbe = QStringLiteral("startup-probe");

} // namespace

void StartupProbe::addTo(QCommandLineParser& parser)
{
    parser.addOption(
        {kStartupProbe, QApplication::translate("main", "Print how long the start took once the "
                                                        "window shows the bus's drives, then quit "
                                                        "(for measurements).")});
}

void StartupProbe::apply(const QCommandLineParser& parser, MainWindow* window,
                         const QElapsedTimer& sinceMain)
{
    if (!parser.isSet(kStartupProbe))
        return;
    auto* probe = new StartupProbe(window, sinceMain);
    qApp->installEventFilter(probe);
}

StartupProbe::StartupProbe(MainWindow* window, const QElapsedTimer& sinceMain)
    : QObject(window)
    , m_window(window)
    , m_sinceMain(sinceMain)
{
}

bool StartupProbe::usable() const
{
    return m_window->isVisible() && m_window->drives() && !m_window->drives()->slaves().isEmpty();
}

bool StartupProbe::eventFilter(QObject* watched, QEvent* event)
{
    // The first paint after the drives are listed is the window a user can work with.
    if (!m_done && event->type() == QEvent::Paint && usable()) {
        m_done = true;
        QTimer::singleShot(0, this, [this] {
            std::printf("ready: %.0f ms after main()\n", double(m_sinceMain.nsecsElapsed()) / 1e6);
            std::fflush(stdout);
            QApplication::quit();
        });
    }
    return QObject::eventFilter(watched, event);
}

} // namespace opentop
