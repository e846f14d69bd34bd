// opentop-cli: the command line. Composition root only; the commands live in cli/.
#include "cli/CliApp.h"
#include "cli/CliContext.h"
#include "model/i18n/Language.h"
#include "model/monitor/LocalTimeZone.h"
#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QLoggingCategory>
#include <QTextStream>
#include <cstdio>
#include <memory>

int main(int argc, char* argv[])
{
    opentop::LocalTimeZone::readOnce();
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    // Only a certificate's PDF needs Qt Gui (its text layout); it draws offscreen, never on a
    // display, so it works over ssh and on a station without one.
    std::unique_ptr<QCoreApplication> app;
    if (opentop::CliApp::needsGui(arguments)) {
        qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
        app = std::make_unique<QGuiApplication>(argc, argv);
    } else {
        app = std::make_unique<QCoreApplication>(argc, argv);
    }
    // Every failure reaches the user as the command's own message; the modules' log lines are
    // for developers (QT_LOGGING_RULES="opentop.*=true" shows them again).
    QLoggingCategory::setFilterRules(QStringLiteral("opentop.*.warning=false"));
    QCoreApplication::setApplicationName(QStringLiteral("opentop-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(OPENTOP_VERSION));
    // --lang, else the system locale; before the parser, whose help is translated.
    QString languageError;
    if (!opentop::Language::installFor(opentop::Language::requestedIn(arguments), QString(),
                                       &languageError)) {
        std::fprintf(stderr, "opentop-cli: %s\n", qPrintable(languageError));
        return 2;
    }
    // --json output is an interface: its device texts stay English in every language.
    opentop::ProfileRegistry::setLanguage(
        opentop::CliApp::profileLanguage(arguments, opentop::Language::current()));
    opentop::CliContext::installInterruptHandler();
    QTextStream out(stdout);
    QTextStream err(stderr);
    opentop::CliApp cli;
    const int code = cli.run(QCoreApplication::arguments(), out, err);
    return opentop::CliApp::finishOutput(
        code, out, err, [] { return std::fflush(stdout) != 0 || std::ferror(stdout) != 0; });
}
