// opentop-soak: hours of monitoring every drive of a 247-drive bus, measured (tests/soak,
// docs/soak.md).
#include "SoakOptions.h"
#include "SoakRun.h"

#include <QCoreApplication>
#include <QTextStream>
#include <QTimer>
#include <cstdio>

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
    QTimer::singleShot(0, &run, &opentop::soak::SoakRun::start);
    return app.exec();
}
