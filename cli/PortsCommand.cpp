#include "cli/PortsCommand.h"

#include "cli/CliContext.h"
#include "cli/TextTable.h"
#include "transport/SerialPortList.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace opentop {

QString PortsCommand::summary() const
{
    return QCoreApplication::translate("opentop::PortsCommand",
                                       "List serial ports and USB adapters");
}

int PortsCommand::run(CliContext& context, const QStringList& args)
{
    if (!args.isEmpty()) {
        context.err() << QCoreApplication::translate("opentop::PortsCommand",
                                                     "error: ports takes no arguments")
                      << Qt::endl;
        return ExitUsage;
    }
    const QVector<SerialPortList::Port> ports = SerialPortList::available();
    if (context.json()) {
        QJsonArray list;
        for (const SerialPortList::Port& p : ports) {
            list.append(QJsonObject{{QStringLiteral("port"), p.systemLocation},
                                    {QStringLiteral("description"), p.description},
                                    {QStringLiteral("manufacturer"), p.manufacturer},
                                    {QStringLiteral("serialNumber"), p.serialNumber},
                                    {QStringLiteral("vidPid"), p.vidPid()}});
        }
        context.out() << QJsonDocument(QJsonObject{{QStringLiteral("ports"), list}})
                             .toJson(QJsonDocument::Indented);
        return ExitOk;
    }
    if (ports.isEmpty()) {
        context.out() << QCoreApplication::translate("opentop::PortsCommand",
                                                     "No serial ports found.")
                      << '\n';
    } else {
        TextTable table({QCoreApplication::translate("opentop::PortsCommand", "Port"),
                         QCoreApplication::translate("opentop::PortsCommand", "Adapter"),
                         QCoreApplication::translate("opentop::PortsCommand", "Manufacturer"),
                         QCoreApplication::translate("opentop::PortsCommand", "Serial no."),
                         QCoreApplication::translate("opentop::PortsCommand", "VID:PID")});
        for (const SerialPortList::Port& p : ports)
            table.addRow(
                {p.systemLocation, p.description, p.manufacturer, p.serialNumber, p.vidPid()});
        table.print(context.out());
    }
    context.out() << SerialPortList::typedPathHint() << Qt::endl;
    return ExitOk;
}

} // namespace opentop
