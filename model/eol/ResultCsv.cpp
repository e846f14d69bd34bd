#include "model/eol/ResultCsv.h"

#include "model/eol/UnitRecordJson.h"
#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"

namespace opentop {

namespace {

QString shortest(double value)
{
    // The shortest text that reads back as the same double.
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

} // namespace

QString ResultCsv::field(const QString& text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) &&
        !text.contains(QLatin1Char('\n')) && !text.contains(QLatin1Char('\r')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QByteArray ResultCsv::line(const QStringList& fields)
{
    // Serials, names and reasons come from stations and operators: no control character and no
    // formula reaches a spreadsheet (DisplayText::csvCell); numbers such as -12.5 stay numbers.
    QStringList out;
    for (const QString& f : fields)
        out.append(field(DisplayText::csvCell(f)));
    return out.join(QLatin1Char(',')).toUtf8() + "\r\n";
}

QByteArray ResultCsv::units(const QVector<UnitRecord>& units)
{
    QByteArray csv =
        line({QStringLiteral("unit_id"), QStringLiteral("serial"), QStringLiteral("station"),
              QStringLiteral("operator"), QStringLiteral("started_utc"),
              QStringLiteral("ended_utc"), QStringLiteral("recipe"),
              QStringLiteral("recipe_revision"), QStringLiteral("recipe_checksum"),
              QStringLiteral("status"), QStringLiteral("failure_reason")});
    for (const UnitRecord& u : units)
        csv += line({u.id, u.serial, u.station, u.operatorName, UnitRecordJson::timeText(u.started),
                     UnitRecordJson::timeText(u.ended), u.recipeName, u.recipeRevision,
                     u.recipeChecksum, unitStatusName(u.status), u.failureReason});
    return csv;
}

QByteArray ResultCsv::measurements(const QVector<UnitRecord>& records)
{
    QByteArray csv =
        line({QStringLiteral("unit_id"), QStringLiteral("serial"), QStringLiteral("machine_number"),
              QStringLiteral("step"), QStringLiteral("quantity"), QStringLiteral("value"),
              QStringLiteral("unit"), QStringLiteral("lower_limit"), QStringLiteral("upper_limit"),
              QStringLiteral("verdict")});
    for (const UnitRecord& r : records)
        for (const Measurement& m : r.measurements)
            csv += line({r.id, r.serial, QString::number(m.machineNumber), m.step, m.quantity,
                         shortest(m.value), m.unit, m.lower ? shortest(*m.lower) : QString(),
                         m.upper ? shortest(*m.upper) : QString(),
                         m.pass ? QStringLiteral("pass") : QStringLiteral("fail")});
    return csv;
}

QByteArray ResultCsv::yield(const QVector<YieldRow>& rows)
{
    QByteArray csv = line(
        {QStringLiteral("recipe"), QStringLiteral("revision"), QStringLiteral("checksum"),
         QStringLiteral("shift"), QStringLiteral("serials"), QStringLiteral("first_pass"),
         QStringLiteral("first_pass_yield"), QStringLiteral("second_pass"),
         QStringLiteral("second_pass_yield"), QStringLiteral("last_pass"),
         QStringLiteral("last_pass_yield"), QStringLiteral("records"), QStringLiteral("passed"),
         QStringLiteral("failed"), QStringLiteral("station_errors"), QStringLiteral("not_finished"),
         QStringLiteral("reason_kind"), QStringLiteral("reason"), QStringLiteral("count")});
    for (const YieldRow& r : rows) {
        const QStringList head{r.recipe,
                               r.revision,
                               r.checksum,
                               r.shift,
                               QString::number(r.serials),
                               QString::number(r.firstPass),
                               shortest(r.firstPassYield()),
                               QString::number(r.secondPass),
                               shortest(r.secondPassYield()),
                               QString::number(r.lastPass),
                               shortest(r.lastPassYield()),
                               QString::number(r.records),
                               QString::number(r.passed),
                               QString::number(r.failed),
                               QString::number(r.stationErrors),
                               QString::number(r.running)};
        if (r.failureReasons.isEmpty() && r.stationReasons.isEmpty())
            csv += line(head + QStringList{QString(), QString(), QStringLiteral("0")});
        for (auto it = r.failureReasons.cbegin(); it != r.failureReasons.cend(); ++it)
            csv += line(head +
                        QStringList{QStringLiteral("fail"), it.key(), QString::number(it.value())});
        for (auto it = r.stationReasons.cbegin(); it != r.stationReasons.cend(); ++it)
            csv += line(head + QStringList{QStringLiteral("station"), it.key(),
                                           QString::number(it.value())});
    }
    return csv;
}

bool ResultCsv::save(const QString& path, const QByteArray& csv, QString* error)
{
    return OutputFile::write(path, csv, error);
}

} // namespace opentop
