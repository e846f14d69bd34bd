// opentop-cli: the command line. Composition root only; the commands live in cli/.
#include "CliApp.h"
#include "CliContext.h"

#include <QCoreApplication>
#include <QTextStream>
#include <cstdio>

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("opentop-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(OPENTOP_VERSION));
    opentop::CliContext::installInterruptHandler();
    QTextStream out(stdout);
    QTextStream err(stderr);
    opentop::CliApp cli;
    return cli.run(QCoreApplication::arguments(), out, err);
}
