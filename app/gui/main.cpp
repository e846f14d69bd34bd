// opentop: the desktop application. Composition root only: options, the backend factory and
// the main window.
#include "BackendFactory.h"
#include "ConnectionOptions.h"
#include "ModbusClient.h"
#include "MonitorOptions.h"
#include "TrafficLog.h"
#include "bus/BusSpec.h"
#include "connection/ConnectionDialog.h"
#include "main/MainWindow.h"
#include "pages/EditorRegistry.h"

#include <QApplication>
#include <QCommandLineParser>
#include <cstdio>

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("OpenTOP"));
    QApplication::setApplicationName(QStringLiteral("OpenTOP"));
    QApplication::setApplicationVersion(QStringLiteral(OPENTOP_VERSION));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Commissioning tool for RS-485 Modbus-RTU motor drives."));
    parser.addHelpOption();
    parser.addVersionOption();
    opentop::ConnectionOptions::addTo(parser);
    opentop::MonitorOptions::addTo(parser);
    parser.process(app);
    opentop::registerBuiltInEditors();

    // A connection on the command line wins; otherwise the last one used; otherwise a
    // simulated bus, so that the program can be tried without hardware.
    bool remembered = false;
    opentop::ConnectionSettings settings = opentop::ConnectionDialog::remembered(&remembered);
    const bool named = parser.isSet(QStringLiteral("sim")) ||
                       parser.isSet(QStringLiteral("port")) || parser.isSet(QStringLiteral("tcp"));
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
    if (!opentop::MonitorOptions::apply(parser, &window, &optionError)) {
        std::fprintf(stderr, "opentop: %s\n", qPrintable(optionError));
        return 2;
    }
    window.show();
    window.connectTo(settings, settings.kind == opentop::ConnectionSettings::Kind::Simulated
                                   ? known
                                   : QHash<int, QString>());
    return app.exec();
}
