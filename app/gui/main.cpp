// opentop: the desktop application. Composition root only: options, the backend factory and
// the main window.
#include "app/gui/MonitorOptions.h"
#include "app/gui/ProductionOptions.h"
#include "app/gui/StartupProbe.h"
#include "connection/BackendFactory.h"
#include "connection/ConnectionOptions.h"
#include "model/bus/BusSpec.h"
#include "model/i18n/Language.h"
#include "model/monitor/LocalTimeZone.h"
#include "transport/ModbusClient.h"
#include "transport/TrafficLog.h"
#include "ui/connection/ConnectionDialog.h"
#include "ui/i18n/LanguageFont.h"
#include "ui/main/MainWindow.h"
#include "ui/pages/EditorRegistry.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QIcon>
#include <cstdio>
#include <cstring>

int main(int argc, char* argv[])
{
    QElapsedTimer sinceMain; // --startup-probe
    sinceMain.start();
    opentop::LocalTimeZone::readOnce();
    // --version and --help only print: they work without a display (an ssh session, a build).
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--version") == 0 || std::strcmp(argv[i], "-v") == 0) {
            std::printf("opentop %s\n", OPENTOP_VERSION);
            return 0;
        }
        const bool help = std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0 ||
                          std::strcmp(argv[i], "-?") == 0 ||
                          std::strcmp(argv[i], "--help-all") == 0;
        if (help && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("OpenTOP"));
    QApplication::setApplicationName(QStringLiteral("OpenTOP"));
    QApplication::setApplicationVersion(QStringLiteral(OPENTOP_VERSION));
    // One id for the desktop entry, the icon and the AppStream metainfo (packaging/).
    QApplication::setDesktopFileName(QStringLiteral("io.github.opentop.OpenTOP"));
    QIcon icon;
    for (int size : {16, 24, 32, 48, 64, 128, 256})
        icon.addFile(QStringLiteral(":/icons/%1/opentop.png").arg(size), QSize(size, size));
    QApplication::setWindowIcon(icon);
    // Before any text is made: the help below is already in the chosen language.
    QString languageError;
    if (!opentop::Language::installFor(opentop::Language::requestedIn(argc, argv),
                                       opentop::Language::saved(), &languageError)) {
        std::fprintf(stderr, "opentop: %s\n", qPrintable(languageError));
        return 2;
    }
    opentop::LanguageFont::apply(opentop::Language::current());
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Commissioning tool for RS-485 Modbus-RTU motor drives."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({QStringLiteral("lang"),
                      QApplication::translate("main", "Language of the program: %1 (default: "
                                                      "the language menu's choice, else the "
                                                      "system's).")
                          .arg(opentop::Language::available().join(QStringLiteral(", "))),
                      QStringLiteral("code")});
    opentop::ConnectionOptions::addTo(parser);
    opentop::MonitorOptions::addTo(parser);
    opentop::ProductionOptions::addTo(parser);
    opentop::StartupProbe::addTo(parser);
    parser.process(app);
    opentop::registerBuiltInEditors();

    // A connection on the command line wins; otherwise the last one used; otherwise a
    // simulated bus, so that the program can be tried without hardware.
    bool remembered = false;
    opentop::ConnectionSettings settings = opentop::ConnectionDialog::remembered(&remembered);
    // Serial-line options without --port are refused by fromParser(), never silently dropped.
    const bool named = parser.isSet(QStringLiteral("sim")) ||
                       parser.isSet(QStringLiteral("port")) ||
                       parser.isSet(QStringLiteral("tcp")) ||
                       opentop::ConnectionOptions::hasSerialLineOptions(parser);
    QString error;
    if (named || !remembered) {
        const auto parsed = opentop::ConnectionOptions::fromParser(
            parser, QStringLiteral("dbu200@1,dbu400@150,dcpid@7"), &error);
        if (!parsed) {
            std::fprintf(stderr, "opentop: %s\n", qPrintable(error));
            return 2;
        }
        settings = *parsed;
    }
    QHash<int, QString> known;
    for (const auto& e : opentop::BusSpec::parse(settings.simSpec, nullptr)
                             .value_or(QVector<opentop::BusSpecEntry>()))
        known.insert(e.slave, e.type);

    opentop::MainWindow window(
        [](const opentop::ConnectionSettings& s, opentop::TrafficLog* log, QString* e) {
            auto made = opentop::BackendFactory::makeClient(s, log);
            if (e)
                *e = made.error;
            return std::move(made.client);
        });
    // Before the window shows and connects: a bad value ends the program with nothing opened.
    QString optionError;
    if (!opentop::MonitorOptions::apply(parser, &window, &optionError) ||
        !opentop::ProductionOptions::apply(parser, &window, &optionError)) {
        std::fprintf(stderr, "opentop: %s\n", qPrintable(optionError));
        return 2;
    }
    opentop::StartupProbe::apply(parser, &window, sinceMain);
    window.show();
    window.connectTo(settings, settings.kind == opentop::ConnectionSettings::Kind::Simulated
                                   ? known
                                   : QHash<int, QString>());
    return app.exec();
}
