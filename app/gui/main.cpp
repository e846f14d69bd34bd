// opentop: the desktop application. Composition root only: parse options, make the bus
// client, show the main window.
#include "BackendFactory.h"
#include "BusSpec.h"
#include "ConnectionOptions.h"
#include "MainWindow.h"
#include "ModbusClient.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>

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
    parser.process(app);

    QString error;
    const auto settings = opentop::ConnectionOptions::fromParser(
        parser, QStringLiteral("dbu200@1,dbu400@150,dcpid@7"), &error);
    auto made =
        settings ? opentop::BackendFactory::makeClient(*settings) : opentop::BackendFactory::Made{};
    if (!made.client) {
        QMessageBox::critical(nullptr, QApplication::translate("main", "OpenTOP"),
                              settings ? made.error : error);
        return 2;
    }
    QVector<int> expected;
    QHash<int, QString> types;
    if (settings->kind == opentop::ConnectionSettings::Kind::Simulated) {
        const auto entries = opentop::BusSpec::parse(settings->simSpec, nullptr);
        for (const auto& entry : entries.value_or(QVector<opentop::BusSpecEntry>())) {
            expected << entry.slave;
            types.insert(entry.slave, entry.type);
        }
    }
    opentop::MainWindow window(made.client.get(), expected);
    window.setAssignedTypes(types);
    window.show();
    return app.exec();
}
