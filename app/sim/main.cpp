// opentop-sim: simulated TROY DBU drives and DC PID controllers on a pty or Modbus TCP.
#include "SimApp.h"

#include <QCoreApplication>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("opentop-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(OPENTOP_VERSION));
    opentop::SimApp sim;
    const int early = sim.start(QCoreApplication::arguments());
    if (early >= 0)
        return early;
    return QCoreApplication::exec();
}
