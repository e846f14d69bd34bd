// opentop-sim: simulated TROY DBU drives and DC PID controllers on a pty or Modbus TCP.
#include "model/i18n/Language.h"
#include "sim/SimApp.h"

#include <QCoreApplication>
#include <cstdio>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("opentop-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(OPENTOP_VERSION));
    QString languageError;
    if (!opentop::Language::installFor(opentop::Language::requestedIn(argc, argv), QString(),
                                       &languageError)) {
        std::fprintf(stderr, "opentop-sim: %s\n", qPrintable(languageError));
        return 2;
    }
    opentop::SimApp sim;
    const int early = sim.start(QCoreApplication::arguments());
    if (early >= 0)
        return early;
    return QCoreApplication::exec();
}
