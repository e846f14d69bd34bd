// opentop-soak: monitoring every drive of a 247-drive bus for a long time, measured
// (docs/soak.md).
#include "tests/soak/SoakOptions.h"
#include "tests/soak/SoakRun.h"

#include <QCoreApplication>
#include <QSocketNotifier>
#include <QTextStream>
#include <QTimer>
#include <csignal>
#include <unistd.h>

namespace {

int g_signalPipe[2] = {-1, -1};

void onSignal(int)
{
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = ::write(g_signalPipe[1], &byte, 1);
}

} // namespace

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    QTextStream err(stderr);
    QString error;
    bool help = false;
    const auto options = opentop::soak::SoakOptions::parse(app.arguments().mid(1), &error, &help);
    if (help) {
        out << opentop::soak::SoakOptions::usage();
        return 0;
    }
    if (!options) {
        err << "opentop-soak: " << error << Qt::endl;
        return 2;
    }
    opentop::soak::SoakRun run(*options, out);
    QObject::connect(&run, &opentop::soak::SoakRun::finished, &app, &QCoreApplication::exit);
    // Ctrl-C, SIGTERM, SIGHUP: leave through the event loop, so that the simulators and the
    // opentop program this run started are stopped with it.
    if (::pipe(g_signalPipe) == 0) {
        auto* notifier = new QSocketNotifier(g_signalPipe[0], QSocketNotifier::Read, &app);
        QObject::connect(notifier, &QSocketNotifier::activated, &app, [&out] {
            out << "opentop-soak: interrupted" << Qt::endl;
            QCoreApplication::exit(130);
        });
        for (int sig : {SIGINT, SIGTERM, SIGHUP})
            std::signal(sig, onSignal);
    }
    QTimer::singleShot(0, &run, &opentop::soak::SoakRun::start);
    return app.exec();
}
