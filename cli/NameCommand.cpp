#include "cli/NameCommand.h"

#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "cli/TextTable.h"
#include "model/bus/BusMemory.h"
#include "model/bus/DriveName.h"
#include "model/io/DisplayText.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::NameCommand", text);
}

void printJson(CliContext& context, const QHash<int, QString>& names, const QVector<int>& slaves)
{
    QJsonArray list;
    for (int slave : slaves)
        list.append(QJsonObject{{QStringLiteral("slave"), slave},
                                {QStringLiteral("name"), names.value(slave)}});
    context.out() << QJsonDocument(QJsonObject{{QStringLiteral("names"), list}})
                         .toJson(QJsonDocument::Indented);
}

} // namespace

QString NameCommand::summary() const
{
    return tr("Name a machine (\"Infeed conveyor 3\") or show the names of the bus");
}

int NameCommand::run(CliContext& context, const QStringList& args)
{
    if (args.size() > 2) {
        context.err() << tr("error: name takes a machine number and one name; put a name with "
                            "spaces in quotes: name 1 \"Infeed conveyor 3\"")
                      << Qt::endl;
        return ExitUsage;
    }
    QString error;
    const QString key = context.busKey(&error);
    if (key.isEmpty()) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitUsage;
    }
    const QHash<int, QString> names = BusMemory::names(key);
    if (args.isEmpty()) {
        QVector<int> slaves = names.keys().toVector();
        std::sort(slaves.begin(), slaves.end());
        if (context.json()) {
            printJson(context, names, slaves);
        } else if (slaves.isEmpty()) {
            context.err() << tr("No machine of this bus has a name yet; give one with: name ID "
                                "\"TEXT\"")
                          << Qt::endl;
        } else {
            TextTable table({tr("ID"), tr("name")});
            table.setRightAligned(0);
            for (int slave : slaves)
                table.addRow({QString::number(slave), names.value(slave)});
            table.print(context.out());
        }
        return ExitOk;
    }
    bool ok = false;
    const int slave = args.first().toInt(&ok);
    if (!ok || slave < 1 || slave > 247) {
        context.err() << tr("error: \"%1\" is not a machine number 1–247").arg(args.first())
                      << Qt::endl;
        return ExitUsage;
    }
    if (args.size() == 1) {
        if (context.json())
            printJson(context, names, {slave});
        else
            context.out() << (names.contains(slave)
                                  ? DriveName::title(slave, names.value(slave))
                                  : tr("Machine number %1 has no name.").arg(slave))
                          << Qt::endl;
        return ExitOk;
    }
    // The model decides what a name may be; nothing is kept when it refuses.
    if (const QString problem = DriveName::problem(args.at(1)); !problem.isEmpty()) {
        context.err() << tr("error: %1 Nothing was changed.").arg(problem) << Qt::endl;
        return ExitInvalid;
    }
    const QString kept = DriveName::cleaned(args.at(1));
    BusMemory::setName(key, slave, kept);
    QHash<int, QString> now = names;
    if (kept.isEmpty())
        now.remove(slave);
    else
        now.insert(slave, kept);
    if (context.json())
        printJson(context, now, {slave});
    else
        context.out() << (kept.isEmpty() ? tr("Machine number %1 has no name now.").arg(slave)
                                         : tr("%1 is named now; messages, files and scans show it.")
                                               .arg(DriveName::title(slave, kept)))
                      << Qt::endl;
    return ExitOk;
}

} // namespace opentop
