#include "cli/EolResultsCommand.h"

#include "cli/CliContext.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "cli/FileCommandSupport.h"
#include "cli/TextTable.h"
#include "model/eol/CertificateHtml.h"
#include "model/eol/ResultCsv.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/UnitRecordJson.h"
#include "model/io/DisplayText.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTimeZone>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolResultsCommand", text);
}

QString trn(const char* text, int n)
{
    return QCoreApplication::translate("opentop::EolResultsCommand", text, nullptr, n);
}

QString localTime(const QDateTime& time)
{
    return time.isValid() ? time.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"))
                          : QString();
}

QJsonObject yieldJson(const YieldRow& r)
{
    auto counts = [](const QMap<QString, int>& map) {
        QJsonObject o;
        for (auto it = map.cbegin(); it != map.cend(); ++it)
            o.insert(it.key(), it.value());
        return o;
    };
    QJsonObject o{{QStringLiteral("recipe"), r.recipe},
                  {QStringLiteral("revision"), r.revision},
                  {QStringLiteral("checksum"), r.checksum},
                  {QStringLiteral("serials"), r.serials},
                  {QStringLiteral("firstPass"), r.firstPass},
                  {QStringLiteral("firstPassYield"), r.firstPassYield()},
                  {QStringLiteral("secondPass"), r.secondPass},
                  {QStringLiteral("secondPassYield"), r.secondPassYield()},
                  {QStringLiteral("lastPass"), r.lastPass},
                  {QStringLiteral("lastPassYield"), r.lastPassYield()},
                  {QStringLiteral("records"), r.records},
                  {QStringLiteral("passed"), r.passed},
                  {QStringLiteral("failed"), r.failed},
                  {QStringLiteral("stationErrors"), r.stationErrors},
                  {QStringLiteral("notFinished"), r.running},
                  {QStringLiteral("failureReasons"), counts(r.failureReasons)},
                  {QStringLiteral("stationReasons"), counts(r.stationReasons)}};
    if (!r.shift.isEmpty())
        o.insert(QStringLiteral("shift"), r.shift);
    return o;
}

} // namespace

QString EolResultsCommand::summary() const
{
    return tr("List units of the results database, their first-pass yield, or export them as CSV");
}

QList<QCommandLineOption> EolResultsCommand::options() const
{
    return {
        {QStringLiteral("db"),
         tr("The results database: a SQLite file, sqlite:PATH or postgresql://user@host/db "
            "(default: OPENTOP_EOL_DB, else ~/.local/share/opentop/results.db)."),
         tr("URL")},
        {QStringLiteral("serial"),
         tr("results: only this serial number; with * or ? a pattern that ignores case "
            "(\"SN-10*\")."),
         tr("S")},
        {QStringLiteral("since"),
         tr("results: started at or after T (2026-11-24, 2026-11-24T06:00, 8h, 2d, today)."),
         tr("T")},
        {QStringLiteral("until"), tr("results: started before T."), tr("T")},
        {QStringLiteral("recipe"), tr("results: only this recipe (product name)."), tr("NAME")},
        {QStringLiteral("checksum"),
         tr("results: only this version of a recipe (its checksum, as eol recipe check prints "
            "it)."),
         tr("SUM")},
        {QStringLiteral("verdict"),
         tr("results: pass, fail, error (station error), interrupted, aborted or running."),
         tr("V")},
        {QStringLiteral("station"), tr("results: only this station."), tr("NAME")},
        {QStringLiteral("limit"), tr("results: only the newest N units."), tr("N")},
        EolSupport::outputOption(),
        {QStringLiteral("csv"), tr("results: CSV (RFC 4180) on standard output or to -o FILE.")},
        {QStringLiteral("yield"),
         tr("results: first-, second- and last-pass yield and failure reasons per recipe "
            "version and per shift; station errors and aborts are kept out of yield.")},
        {QStringLiteral("shifts"),
         tr("results --yield: the shifts' start times in local time (default 06:00,14:00,22:00)."),
         tr("LIST")},
    };
}

QDateTime EolResultsCommand::parseTime(const QString& text, const QDateTime& now, QString* error)
{
    const QString t = text.trimmed();
    const QRegularExpression relative(QStringLiteral("^(\\d+)\\s*([mhdw])$"));
    if (const QRegularExpressionMatch m = relative.match(t); m.hasMatch()) {
        const qint64 n = m.captured(1).toLongLong();
        const QChar unit = m.captured(2).at(0);
        const qint64 seconds = unit == QLatin1Char('m')   ? 60
                               : unit == QLatin1Char('h') ? 3600
                               : unit == QLatin1Char('d') ? 86400
                                                          : 7 * 86400;
        return now.addSecs(-n * seconds).toUTC();
    }
    if (t == QLatin1String("today"))
        return now.toLocalTime().date().startOfDay().toUTC();
    if (t == QLatin1String("yesterday"))
        return now.toLocalTime().date().addDays(-1).startOfDay().toUTC();
    // QDate reads the date of a date and time too: a date alone is ten characters.
    const QDate date = t.size() == 10 ? QDate::fromString(t, Qt::ISODate) : QDate();
    if (date.isValid())
        return date.startOfDay().toUTC();
    QString iso = t;
    if (iso.size() > 10 && iso.at(10) == QLatin1Char(' '))
        iso[10] = QLatin1Char('T');
    const QDateTime time = QDateTime::fromString(iso, Qt::ISODateWithMs);
    if (time.isValid())
        return time.toUTC();
    if (error)
        *error = tr("\"%1\" is not a time; give 2026-11-24, 2026-11-24T06:00 (local, or with Z "
                    "or +01:00), 8h, 2d, today or yesterday")
                     .arg(text);
    return QDateTime();
}

std::optional<ResultFilter> EolResultsCommand::filter(CliContext& context)
{
    const QCommandLineParser& parser = context.parser();
    auto usage = [&](const QString& problem) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(problem)) << Qt::endl;
        return std::nullopt;
    };
    ResultFilter f;
    f.serial = parser.value(QStringLiteral("serial")).trimmed();
    f.recipe = parser.value(QStringLiteral("recipe")).trimmed();
    f.checksum = parser.value(QStringLiteral("checksum")).trimmed();
    f.station = parser.value(QStringLiteral("station")).trimmed();
    const QDateTime now = QDateTime::currentDateTime();
    for (const char* name : {"since", "until"}) {
        const QString option = QString::fromLatin1(name);
        if (!parser.isSet(option))
            continue;
        QString error;
        const QDateTime time = parseTime(parser.value(option), now, &error);
        if (!time.isValid())
            return usage(tr("--%1: %2").arg(option, error));
        (option == QLatin1String("since") ? f.from : f.to) = time;
    }
    if (f.from.isValid() && f.to.isValid() && f.from >= f.to)
        return usage(
            tr("--since %1 is not before --until %2")
                .arg(parser.value(QStringLiteral("since")), parser.value(QStringLiteral("until"))));
    if (parser.isSet(QStringLiteral("verdict"))) {
        const QString text = parser.value(QStringLiteral("verdict")).trimmed().toLower();
        f.status = unitStatusFromName(text);
        if (!f.status)
            return usage(tr("--verdict \"%1\": give pass, fail, error, interrupted, aborted or "
                            "running")
                             .arg(parser.value(QStringLiteral("verdict"))));
    }
    if (parser.isSet(QStringLiteral("limit"))) {
        bool ok = false;
        f.limit = parser.value(QStringLiteral("limit")).toInt(&ok);
        if (!ok || f.limit < 1)
            return usage(tr("--limit \"%1\": give a number of units from 1")
                             .arg(parser.value(QStringLiteral("limit"))));
    }
    return f;
}

void EolResultsCommand::printUnits(CliContext& context, const QVector<UnitRecord>& units)
{
    QTextStream& out = context.out();
    if (units.isEmpty()) {
        out << tr("no unit matches") << Qt::endl;
        return;
    }
    TextTable table({tr("started"), tr("serial"), tr("recipe"), tr("approved by"), tr("station"),
                     tr("operator"), tr("drives"), tr("verdict"), tr("time"), tr("reason")});
    for (const UnitRecord& u : units) {
        const QString seconds =
            u.ended.isValid()
                ? QString::number(double(u.started.msecsTo(u.ended)) / 1000.0, 'f', 1) +
                      QStringLiteral(" s")
                : QString();
        QStringList drives;
        for (const UnitDrive& d : u.drives)
            drives << tr("%1: %2").arg(d.machineNumber).arg(CertificateHtml::variantText(d));
        table.addRow({localTime(u.started), u.serial,
                      tr("%1 rev. %2").arg(u.recipeName, u.recipeRevision), u.approver, u.station,
                      u.operatorName, drives.join(QStringLiteral("; ")),
                      CertificateHtml::verdictText(u.status), seconds,
                      u.isPass() ? QString() : YieldReport::reasonOf(u)});
    }
    table.setRightAligned(7);
    table.print(out);
    out << trn("%n unit(s)", int(units.size())) << Qt::endl;
}

void EolResultsCommand::printYield(CliContext& context, const QVector<YieldRow>& perRecipe,
                                   const QVector<YieldRow>& perShift)
{
    QTextStream& out = context.out();
    if (perRecipe.isEmpty()) {
        out << tr("no unit matches") << Qt::endl;
        return;
    }
    auto table = [&](const QVector<YieldRow>& rows, bool shifts) {
        QStringList headers{tr("recipe")};
        if (shifts)
            headers << tr("shift");
        headers << tr("serials") << tr("first pass") << tr("second pass") << tr("last pass")
                << tr("passed") << tr("failed") << tr("station errors") << tr("not finished");
        TextTable t(headers);
        auto share = [](int n, double yield) {
            return QStringLiteral("%1 (%2)").arg(n).arg(YieldReport::percentText(yield));
        };
        for (const YieldRow& r : rows) {
            QStringList cells{r.title()};
            if (shifts)
                cells << r.shift;
            cells << QString::number(r.serials) << share(r.firstPass, r.firstPassYield())
                  << share(r.secondPass, r.secondPassYield())
                  << share(r.lastPass, r.lastPassYield()) << QString::number(r.passed)
                  << QString::number(r.failed) << QString::number(r.stationErrors)
                  << QString::number(r.running);
            t.addRow(cells);
        }
        for (int c = shifts ? 2 : 1; c < headers.size(); ++c)
            t.setRightAligned(c);
        t.print(out);
    };
    out << tr("Yield per recipe version (station errors and aborts are not counted)") << '\n';
    table(perRecipe, false);
    // Two versions of one recipe name are told apart by their checksums.
    QHash<QString, int> versions;
    for (const YieldRow& r : perRecipe)
        ++versions[r.title()];
    for (const YieldRow& r : perRecipe)
        if (versions.value(r.title()) > 1)
            out << "  "
                << tr("%1: checksum %2")
                       .arg(DisplayText::escaped(r.title()), DisplayText::escaped(r.checksum))
                << '\n';
    out << '\n' << tr("Per shift") << '\n';
    table(perShift, true);
    auto reasons = [&](const QString& title, QMap<QString, int> YieldRow::*which) {
        bool any = false;
        for (const YieldRow& r : perRecipe) {
            const QMap<QString, int>& map = r.*which;
            for (auto it = map.cbegin(); it != map.cend(); ++it) {
                if (!any)
                    out << '\n' << title << '\n';
                any = true;
                out << QStringLiteral("  %1  %2: %3\n")
                           .arg(it.value(), 4)
                           .arg(DisplayText::escaped(r.title()), DisplayText::escaped(it.key()));
            }
        }
    };
    reasons(tr("Failure reasons"), &YieldRow::failureReasons);
    reasons(tr("Station errors (not counted in yield)"), &YieldRow::stationReasons);
    out.flush();
}

int EolResultsCommand::output(CliContext& context, const QByteArray& csv)
{
    const QString path = context.parser().value(QStringLiteral("o"));
    if (path.isEmpty()) {
        context.out() << QString::fromUtf8(csv);
        context.out().flush();
        return ExitOk;
    }
    QString error;
    if (!ResultCsv::save(path, csv, &error)) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitUsage;
    }
    context.err() << tr("wrote %1").arg(DisplayText::escaped(path)) << Qt::endl;
    return ExitOk;
}

int EolResultsCommand::run(CliContext& context, const QStringList& args)
{
    const QCommandLineParser& parser = context.parser();
    if (!args.isEmpty()) {
        context.err() << tr("error: unexpected argument \"%1\"; usage: eol %2")
                             .arg(DisplayText::escaped(args.first()), synopsis())
                      << Qt::endl;
        return ExitUsage;
    }
    const bool csv = parser.isSet(QStringLiteral("csv"));
    if (csv && context.json()) {
        context.err() << tr("error: give --csv or --json, not both") << Qt::endl;
        return ExitUsage;
    }
    if (parser.isSet(QStringLiteral("o")) && !csv) {
        context.err() << tr("error: -o names the CSV file: give --csv too") << Qt::endl;
        return ExitUsage;
    }
    const bool yield = parser.isSet(QStringLiteral("yield"));
    if (parser.isSet(QStringLiteral("shifts")) && !yield) {
        context.err() << tr("error: --shifts is for --yield") << Qt::endl;
        return ExitUsage;
    }
    ShiftPlan plan;
    if (parser.isSet(QStringLiteral("shifts"))) {
        QString error;
        const std::optional<ShiftPlan> given = ShiftPlan::parse(
            parser.value(QStringLiteral("shifts")), QTimeZone::systemTimeZone(), &error);
        if (!given) {
            context.err() << tr("error: --shifts %1: %2")
                                 .arg(DisplayText::escaped(parser.value(QStringLiteral("shifts"))),
                                      DisplayText::escapedLines(error))
                          << Qt::endl;
            return ExitUsage;
        }
        plan = *given;
    }
    const std::optional<ResultFilter> f = filter(context);
    if (!f)
        return ExitUsage;
    int code = ExitOk;
    const std::unique_ptr<ResultDatabase> db = EolSupport::openDatabase(context, &code);
    if (!db)
        return code;
    QString error;
    if (yield) {
        const std::optional<YieldReport::Tables> tables = YieldReport::query(*db, *f, plan, &error);
        if (!tables) {
            context.err() << tr("error: %1: %2")
                                 .arg(DisplayText::escaped(db->url().displayText()),
                                      DisplayText::escapedLines(error))
                          << Qt::endl;
            return ExitCommunication;
        }
        const QVector<YieldRow>& perRecipe = tables->perRecipe;
        const QVector<YieldRow>& perShift = tables->perShift;
        if (csv)
            return output(context, ResultCsv::yield(perRecipe + perShift));
        if (context.json()) {
            QJsonArray recipes;
            for (const YieldRow& r : perRecipe)
                recipes << yieldJson(r);
            QJsonArray shifts;
            for (const YieldRow& r : perShift)
                shifts << yieldJson(r);
            FileCommandSupport::printJson(
                context, {{QStringLiteral("command"), QStringLiteral("eol results")},
                          {QStringLiteral("database"), db->url().displayText()},
                          {QStringLiteral("perRecipe"), recipes},
                          {QStringLiteral("perShift"), shifts}});
            return ExitOk;
        }
        printYield(context, perRecipe, perShift);
        return ExitOk;
    }
    const ResultQueries queries(*db);
    const std::optional<QVector<UnitRecord>> units = queries.find(*f, &error);
    if (!units) {
        context.err() << tr("error: %1: %2")
                             .arg(DisplayText::escaped(db->url().displayText()),
                                  DisplayText::escapedLines(error))
                      << Qt::endl;
        return ExitCommunication;
    }
    if (csv)
        return output(context, ResultCsv::units(*units));
    // Each drive's variant and how it was known (read, probed, confirmed, assumed).
    QVector<UnitRecord> listed = *units;
    if (!queries.addDrives(&listed, &error)) {
        context.err() << tr("error: %1: %2")
                             .arg(DisplayText::escaped(db->url().displayText()),
                                  DisplayText::escapedLines(error))
                      << Qt::endl;
        return ExitCommunication;
    }
    if (context.json()) {
        QJsonArray array;
        for (const UnitRecord& u : listed)
            array << UnitRecordJson::toJson(u);
        FileCommandSupport::printJson(context,
                                      {{QStringLiteral("command"), QStringLiteral("eol results")},
                                       {QStringLiteral("database"), db->url().displayText()},
                                       {QStringLiteral("units"), array}});
        return ExitOk;
    }
    printUnits(context, listed);
    return ExitOk;
}

} // namespace opentop
