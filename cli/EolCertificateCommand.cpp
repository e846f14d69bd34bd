#include "cli/EolCertificateCommand.h"

#include "cli/CliContext.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "model/eol/CertificateHtml.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/UnitRecordJson.h"
#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"
#include "report/CertificatePdf.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QRegularExpression>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolCertificateCommand", text);
}

} // namespace

QString EolCertificateCommand::summary() const
{
    return tr("A unit's certificate: its newest record as a PDF, or as JSON with --json");
}

QList<QCommandLineOption> EolCertificateCommand::options() const
{
    return {
        {QStringLiteral("db"), tr("The results database (see results)."), tr("URL")},
        {QStringLiteral("id"), tr("certificate: the record with this id instead of the newest."),
         tr("ID")},
        EolSupport::outputOption(),
    };
}

QString EolCertificateCommand::defaultFile(const QString& serial)
{
    QString name = serial;
    name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9._-]")), QStringLiteral("_"));
    if (name.startsWith(QLatin1Char('.')))
        name.prepend(QLatin1Char('_'));
    return name + QStringLiteral(".pdf");
}

int EolCertificateCommand::run(CliContext& context, const QStringList& args)
{
    const QCommandLineParser& parser = context.parser();
    const QString id = parser.value(QStringLiteral("id")).trimmed();
    const bool byId = parser.isSet(QStringLiteral("id"));
    if (args.size() > 1 || (args.isEmpty() && !byId) || (byId && id.isEmpty())) {
        context.err() << tr("error: name one serial number, or a record with --id ID; usage: "
                            "eol %1")
                             .arg(synopsis())
                      << Qt::endl;
        return ExitUsage;
    }
    const QString serial = args.value(0).trimmed();
    if (!args.isEmpty() && serial.isEmpty()) {
        context.err() << tr("error: the serial number is empty") << Qt::endl;
        return ExitUsage;
    }
    const QString path = parser.value(QStringLiteral("o"));
    if (!path.isEmpty()) {
        if (const QString problem = OutputFile::problem(path); !problem.isEmpty()) {
            context.err() << tr("error: %1").arg(DisplayText::escapedLines(problem)) << Qt::endl;
            return ExitUsage;
        }
    }
    const bool pdf = !context.json();
    if (pdf && !qobject_cast<QGuiApplication*>(QCoreApplication::instance())) {
        // opentop-cli makes a QGuiApplication for this command (CliApp::needsGui).
        context.err() << tr("error: this program cannot draw a PDF (no Qt GUI application); "
                            "use --json")
                      << Qt::endl;
        return ExitUsage;
    }

    int code = ExitOk;
    const std::unique_ptr<ResultDatabase> db = EolSupport::openDatabase(context, &code);
    if (!db)
        return code;
    ResultQueries queries(*db);
    QString error;
    std::optional<UnitRecord> record;
    if (byId) {
        record = queries.load(id, &error);
        if (!record) {
            context.err() << tr("error: no record %1 in %2 (%3)")
                                 .arg(DisplayText::escaped(id),
                                      DisplayText::escaped(db->url().displayText()),
                                      DisplayText::escapedLines(error))
                          << Qt::endl;
            return ExitInvalid;
        }
        if (!serial.isEmpty() && record->serial != serial) {
            context.err() << tr("error: record %1 is of serial number %2, not %3")
                                 .arg(DisplayText::escaped(id),
                                      DisplayText::escaped(record->serial),
                                      DisplayText::escaped(serial))
                          << Qt::endl;
            return ExitUsage;
        }
    } else {
        const std::optional<QVector<UnitRecord>> history = queries.history(serial, &error);
        if (!history) {
            context.err() << tr("error: %1: %2")
                                 .arg(DisplayText::escaped(db->url().displayText()),
                                      DisplayText::escapedLines(error))
                          << Qt::endl;
            return ExitCommunication;
        }
        if (history->isEmpty()) {
            context.err() << tr("error: no record of serial number %1 in %2")
                                 .arg(DisplayText::escaped(serial),
                                      DisplayText::escaped(db->url().displayText()))
                          << Qt::endl;
            return ExitInvalid;
        }
        record = history->last(); // oldest first
    }

    if (!pdf) {
        const QByteArray json = UnitRecordJson::toBytes(*record);
        if (path.isEmpty()) {
            context.out() << QString::fromUtf8(json);
            context.out().flush();
            return ExitOk;
        }
        if (!OutputFile::write(path, json, &error)) {
            context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
            return ExitUsage;
        }
        context.err() << tr("wrote %1").arg(DisplayText::escaped(path)) << Qt::endl;
        return ExitOk;
    }
    const QString file = path.isEmpty() ? defaultFile(record->serial) : path;
    const std::optional<QVector<UnitRecord>> earlier = queries.earlierOf(*record, &error);
    if (!earlier) {
        context.err() << tr("error: %1: %2")
                             .arg(DisplayText::escaped(db->url().displayText()),
                                  DisplayText::escapedLines(error))
                      << Qt::endl;
        return ExitCommunication;
    }
    if (!CertificatePdf::save(*record, file, &error, *earlier)) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitUsage;
    }
    context.out() << tr("wrote %1: serial number %2, %3, recorded %4")
                         .arg(DisplayText::escaped(file), DisplayText::escaped(record->serial),
                              CertificateHtml::verdictText(record->status),
                              UnitRecordJson::timeText(record->started))
                  << Qt::endl;
    return ExitOk;
}

} // namespace opentop
