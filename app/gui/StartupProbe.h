#pragma once

#include <QElapsedTimer>
#include <QObject>

class QCommandLineParser;

namespace opentop {

class MainWindow;

// --startup-probe (for opentop-bench startup): once the window is connected, lists the bus's
// drives and has painted after that, prints "ready: N ms after main()" and quits.
class StartupProbe : public QObject
{
    Q_OBJECT
public:
    static void addTo(QCommandLineParser& parser);
    // Installs the probe when the option is set; `sinceMain` was started first thing in main().
    static void apply(const QCommandLineParser& parser, MainWindow* window,
                      const QElapsedTimer& sinceMain);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    StartupProbe(MainWindow* window, const QElapsedTimer& sinceMain);
    bool usable() const;

    MainWindow* m_window;
    QElapsedTimer m_sinceMain;
    bool m_done = false;
};

} // namespace opentop
