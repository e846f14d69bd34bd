#include "cli/EolAuditCommand.h"

#include "cli/CliContext.h"
#include "cli/EolResultsCommand.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "cli/TextTable.h"
#include "model/access/AuditTrail.h"
#include "model/eol/ResultDatabase.h"
#include "model/io/DisplayText.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolAuditCommand", text);
}

} // namespace

QString EolAuditCommand::synopsis() const
{
    return QStringLiteral("audit [--since T] [--user NAME] [--station NAME] [--db URL] [--json]");
}

QString EolAuditCommand::summary() const
{
    return tr("Show the audit trail: who logged in, approved, used or was refused a privilege");
}

QList<QCommandLineOption> EolAuditCommand::options() const
{
    return {
        {QStringLiteral("db"), tr("Results database: an SQLite file or postgresql://user@host/db."),
         tr("URL")},
        {QStringLiteral("since"), tr("audit: at or after T (2026-11-24, 8h, 2d, today)."), tr("T")},
        {QStringLiteral("user"), tr("audit: only this user."), tr("NAME")},
        {QStringLiteral("station"), tr("audit: only this station."), tr("NAME")},
    };
}

int EolAuditCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& err = context.err();
    const QCommandLineParser& parser = context.parser();
    if (!args.isEmpty()) {
        err << tr("usage: opentop-cli eol %1").arg(synopsis()) << Qt::endl;
        return ExitUsage;
    }
    AuditFilter filter;
    QString error;
    if (parser.isSet(QStringLiteral("since"))) {
        filter.since = EolResultsCommand::parseTime(parser.value(QStringLiteral("since")),
                                                    QDateTime::currentDateTime(), &error);
        if (!filter.since.isValid()) {
            err << tr("error: --since: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
            return ExitUsage;
        }
    }
    filter.user = parser.value(QStringLiteral("user")).trimmed();
    filter.station = parser.value(QStringLiteral("station")).trimmed();
    int code = ExitOk;
    std::unique_ptr<ResultDatabase> db = EolSupport::openDatabase(context, &code);
    if (!db)
        return code;
    const auto entries = AuditTrail(*db).query(filter, &error);
    if (!entries) {
        err << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitCommunication;
    }
    if (context.json()) {
        QJsonArray array;
        for (const AuditEntry& e : *entries)
            array << QJsonObject{{QStringLiteral("time"), e.time.toString(Qt::ISODateWithMs)},
                                 {QStringLiteral("station"), e.station},
                                 {QStringLiteral("user"), e.user},
                                 {QStringLiteral("action"), e.action},
                                 {QStringLiteral("detail"), e.detail}};
        context.out() << QJsonDocument(array).toJson(QJsonDocument::Indented);
        return ExitOk;
    }
    if (entries->isEmpty()) {
        context.out() << tr("no audit entry matches") << Qt::endl;
        return ExitOk;
    }
    TextTable table({tr("time"), tr("station"), tr("user"), tr("action"), tr("detail")});
    for (const AuditEntry& e : *entries)
        table.addRow({e.time.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
                      e.station, e.user, e.action, e.detail});
    table.print(context.out());
    return ExitOk;
}

} // namespace opentop
