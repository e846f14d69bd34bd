#include "cli/EolRunOutput.h"

#include "cli/CliContext.h"
#include "model/eol/EolRun.h"
#include "model/eol/Recipe.h"
#include "model/eol/UnitRecord.h"
#include "model/io/DisplayText.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolRunOutput", text);
}

QString phaseKey(EolDriveRun::Phase phase)
{
    switch (phase) {
    case EolDriveRun::Phase::Identify:
        return QStringLiteral("identify");
    case EolDriveRun::Phase::Write:
        return QStringLiteral("write");
    case EolDriveRun::Phase::Verify:
        return QStringLiteral("verify");
    case EolDriveRun::Phase::Test:
        return QStringLiteral("test");
    case EolDriveRun::Phase::Done:
        break;
    }
    return QStringLiteral("done");
}

QString limitsText(const Measurement& m)
{
    const auto n = [](double v) { return QString::number(v, 'g', 6); };
    if (m.lower && m.upper)
        return QStringLiteral("%1–%2").arg(n(*m.lower), n(*m.upper));
    if (m.upper)
        return QStringLiteral("≤ %1").arg(n(*m.upper));
    if (m.lower)
        return QStringLiteral("≥ %1").arg(n(*m.lower));
    return QString();
}

// The verdict as the line on standard output says it: with where its record is when that is
// not the results database, so a PASS is never read without its record.
QString verdictText(const EolRun& run, const UnitRecord& record)
{
    const QString verdict = unitStatusName(record.status).toUpper();
    if (!run.storeError().isEmpty())
        return tr("NOT RECORDED (%1)").arg(verdict);
    if (run.spooled())
        return tr("%1 (kept on this station)").arg(verdict);
    return verdict;
}

void jsonLine(CliContext& context, QJsonObject object)
{
    context.out() << QJsonDocument(object).toJson(QJsonDocument::Compact) << '\n';
    context.out().flush();
}

} // namespace

QString EolRunOutput::seconds(const EolRun& run)
{
    return QString::number(run.elapsedMs() / 1000.0, 'f', 1);
}

void EolRunOutput::follow(CliContext& context, EolRun* eol, ModbusClient* client, bool* lost)
{
    CliContext* cli = &context; // the lambdas outlive this call
    const bool json = context.json();
    QObject::connect(eol, &EolRun::phaseChanged, eol,
                     [=](int machineNumber, EolDriveRun::Phase phase, const QString& text) {
                         if (json) {
                             jsonLine(*cli,
                                      {{QStringLiteral("event"), QStringLiteral("phase")},
                                       {QStringLiteral("machineNumber"), machineNumber},
                                       {QStringLiteral("phase"), phaseKey(phase)},
                                       {QStringLiteral("text"), text},
                                       {QStringLiteral("seconds"), eol->elapsedMs() / 1000.0}});
                             return;
                         }
                         // Progress on standard error: standard output is the unit's measurements
                         // and verdict, for scripts.
                         QTextStream& err = cli->err();
                         err << QStringLiteral("[%1 s] %2: %3\n")
                                    .arg(seconds(*eol), tr("drive %1").arg(machineNumber),
                                         DisplayText::escaped(text));
                         err.flush();
                     });
    QObject::connect(eol, &EolRun::measured, eol, [=](const Measurement& m) {
        if (json) {
            QJsonObject o{{QStringLiteral("event"), QStringLiteral("measurement")},
                          {QStringLiteral("machineNumber"), m.machineNumber},
                          {QStringLiteral("step"), m.step},
                          {QStringLiteral("quantity"), m.quantity},
                          {QStringLiteral("value"), m.value},
                          {QStringLiteral("unit"), m.unit},
                          {QStringLiteral("pass"), m.pass}};
            if (m.lower)
                o.insert(QStringLiteral("lower"), *m.lower);
            if (m.upper)
                o.insert(QStringLiteral("upper"), *m.upper);
            jsonLine(*cli, o);
            return;
        }
        const QString limits = limitsText(m);
        QTextStream& out = cli->out();
        out << QStringLiteral("[%1 s] %2: %3 = %4 %5\n")
                   .arg(seconds(*eol), tr("drive %1").arg(m.machineNumber),
                        DisplayText::escaped(m.quantity),
                        DisplayText::escaped(QStringLiteral("%1 %2")
                                                 .arg(QString::number(m.value, 'g', 6), m.unit)
                                                 .trimmed()),
                        (limits.isEmpty()
                             ? QString()
                             : QStringLiteral("(%1) ").arg(DisplayText::escaped(limits))) +
                            (m.pass ? tr("ok") : tr("FAIL")));
        out.flush();
    });
    QObject::connect(client, &ModbusClient::connectionLost, eol,
                     [eol](const QString& why) { eol->connectionLost(why); });
    QObject::connect(client, &ModbusClient::connectionLost, eol,
                     [lost](const QString&) { *lost = true; });
}

void EolRunOutput::verdict(CliContext& context, const EolRun& run, const UnitRecord& record,
                           const Recipe& recipe, const QString& spoolPath)
{
    QTextStream& err = context.err();
    const bool json = context.json();
    QTextStream& out = context.out();
    if (json) {
        QJsonObject o{{QStringLiteral("event"), QStringLiteral("result")},
                      {QStringLiteral("serial"), record.serial},
                      {QStringLiteral("status"), unitStatusName(record.status)},
                      {QStringLiteral("id"), record.id},
                      {QStringLiteral("seconds"), run.elapsedMs() / 1000.0},
                      {QStringLiteral("recorded"), run.storeError().isEmpty()},
                      {QStringLiteral("spooled"), run.spooled()},
                      {QStringLiteral("attempt"), record.attempt}};
        if (!record.failureReason.isEmpty())
            o.insert(QStringLiteral("reason"), record.failureReason);
        if (!run.storeError().isEmpty())
            o.insert(QStringLiteral("recordError"), run.storeError());
        if (!run.unconfirmedStops().isEmpty())
            o.insert(QStringLiteral("notConfirmedStopped"),
                     QJsonValue::fromVariant(run.unconfirmedStops()));
        jsonLine(context, o);
    } else {
        out << QStringLiteral("%1  %2  %3 %4  %5 s%6\n")
                   .arg(DisplayText::escaped(record.serial), verdictText(run, record),
                        DisplayText::escaped(recipe.product),
                        tr("rev. %1").arg(DisplayText::escaped(recipe.revision)), seconds(run),
                        record.attempt > 1
                            ? QStringLiteral("  ") + tr("attempt %1").arg(record.attempt)
                            : QString());
        if (!record.failureReason.isEmpty())
            out << DisplayText::escapedLines(record.failureReason) << '\n';
        out.flush();
    }
    if (!run.storeError().isEmpty())
        err << tr("the result was NOT recorded: %1")
                   .arg(DisplayText::escapedLines(run.storeError()))
            << Qt::endl;
    else if (run.spooled())
        err << tr("the results database did not answer: the result is kept on this station "
                  "(%1) and sent when a station program next reaches the database")
                   .arg(QDir::toNativeSeparators(spoolPath))
            << Qt::endl;
    for (const QString& drive : run.unconfirmedStops())
        err << tr("WARNING: motor not confirmed stopped: %1").arg(DisplayText::escaped(drive))
            << Qt::endl;
}

} // namespace opentop
