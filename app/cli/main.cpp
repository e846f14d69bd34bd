// opentop-cli: the command line. Composition root only; the commands live in cli/.
#include "CliApp.h"
#include "CliContext.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QTextStream>
#include <cstdio>

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    // Every failure reaches the user as the command's own message; the modules' log lines are
    // for developers (QT_LOGGING_RULES="opentop.*=true" shows them again).
    QLoggingCategory::setFilterRules(QStringLiteral("opentop.*.warning=false"));
    QCoreApplication::setApplicationName(QStringLiteral("opentop-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(OPENTOP_VERSION));
    opentop::CliContext::installInterruptHandler();
    QTextStream out(stdout);
    QTextStream err(stderr);
    opentop::CliApp cli;
    return cli.run(QCoreApplication::arguments(), out, err);
}
