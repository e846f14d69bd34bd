#include "cli/AlarmsCommand.h"

#include "cli/CliContext.h"
#include "cli/GroupCheck.h"
#include "cli/TextTable.h"
#include "model/alarms/AlarmHistory.h"
#include "model/bus/DriveName.h"
#include "model/io/DisplayText.h"
#include "model/session/DeviceSession.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::AlarmsCommand", text);
}

QString hexCode(qint64 code)
{
    return QString::number(code, 16).toUpper().rightJustified(2, QLatin1Char('0')) +
           QLatin1Char('h');
}

QString clearedBy(const QString& reset)
{
    return CodeEntry::clearedByText(reset);
}

QJsonObject entryJson(qint64 code, const std::optional<CodeEntry>& e)
{
    QJsonObject o{{QStringLiteral("code"), code}, {QStringLiteral("hex"), hexCode(code)}};
    if (e) {
        o.insert(QStringLiteral("panel"), e->panel);
        o.insert(QStringLiteral("name"), e->name);
        o.insert(QStringLiteral("reset"), e->reset);
        o.insert(QStringLiteral("clearedBy"), e->resetText);
        o.insert(QStringLiteral("cause"), e->cause);
        o.insert(QStringLiteral("remedy"), e->remedy);
    }
    return o;
}

QJsonObject reportJson(const AlarmHistory::Report& report)
{
    QJsonObject root;
    for (const AlarmHistory::History& h : report.histories) {
        QJsonArray records;
        for (const AlarmHistory::Record& r : h.records) {
            QJsonObject o = entryJson(r.code, r.entry);
            o.insert(QStringLiteral("index"), r.index);
            o.insert(QStringLiteral("empty"), r.empty);
            records.append(o);
        }
        QJsonObject table{{QStringLiteral("label"), h.label},
                          {QStringLiteral("used"), h.used()},
                          {QStringLiteral("records"), records}};
        if (!h.ok)
            table.insert(QStringLiteral("error"), h.error);
        root.insert(h.table, table);
    }
    if (!report.commErrorParameter.isEmpty()) {
        QJsonObject comm = report.commErrorCode
                               ? entryJson(*report.commErrorCode, report.commError)
                               : QJsonObject{{QStringLiteral("error"), tr("not read")}};
        comm.insert(QStringLiteral("parameter"), report.commErrorParameter);
        root.insert(QStringLiteral("commError"), comm);
    }
    if (report.alarmActive)
        root.insert(QStringLiteral("alarmActive"), *report.alarmActive);
    if (!report.eraseMethod.isEmpty())
        root.insert(QStringLiteral("powerRestartOnly"), report.powerRestartOnly);
    return root;
}

void printReport(QTextStream& out, const AlarmHistory::Report& report)
{
    if (report.alarmActive) {
        const AlarmHistory::Record* newest = nullptr;
        for (const AlarmHistory::History& h : report.histories) {
            if (h.table == QLatin1String("alarm") && !h.records.isEmpty())
                newest = &h.records.first();
        }
        if (!*report.alarmActive)
            out << tr("No alarm is active.") << '\n';
        else if (newest && newest->entry)
            out << tr("Alarm active: %1 %2.").arg(newest->entry->panel, newest->entry->name)
                << '\n';
        else
            out << tr("An alarm is active.") << '\n';
    }
    if (report.powerRestartOnly)
        out << tr("This drive is set to clear alarms by a power restart only (%1): Alarm-Reset "
                  "clears none of them.")
                   .arg(report.eraseMethod)
            << '\n';
    for (const AlarmHistory::History& h : report.histories) {
        out << '\n';
        if (!h.ok) {
            out << tr("%1: could not be read: %2").arg(h.label, h.error) << '\n';
            continue;
        }
        if (h.used() == 0) {
            out << tr("%1: no records.").arg(h.label) << '\n';
            continue;
        }
        out << tr("%1: %2 of %3 records, newest first")
                   .arg(h.label)
                   .arg(h.used())
                   .arg(h.records.size())
            << '\n';
        TextTable table({tr("#"), tr("Code"), tr("Panel"), tr("Name"), tr("Cleared by")});
        table.setRightAligned(0);
        for (const AlarmHistory::Record& r : h.records) {
            if (r.empty)
                continue;
            table.addRow({QString::number(r.index), hexCode(r.code),
                          r.entry ? r.entry->panel : QString(),
                          r.entry ? r.entry->name : tr("unknown code"),
                          r.entry ? clearedBy(r.entry->reset) : QString()});
        }
        table.print(out);
        for (const CodeEntry& e : h.distinctEntries()) {
            out << '\n' << e.panel << ' ' << e.name << '\n';
            if (!e.cause.isEmpty())
                out << "  " << tr("Cause: %1").arg(e.cause) << '\n';
            if (!e.remedy.isEmpty())
                out << "  " << tr("Remedy: %1").arg(e.remedy) << '\n';
            if (!e.resetText.isEmpty())
                out << "  " << tr("To clear: %1").arg(e.resetText) << '\n';
        }
    }
    if (!report.commErrorParameter.isEmpty()) {
        out << '\n';
        if (!report.commErrorCode)
            out << tr("Communication error register (%1): could not be read.")
                       .arg(report.commErrorParameter)
                << '\n';
        else if (*report.commErrorCode == 0)
            out << tr("Communication error register (%1): none (0).").arg(report.commErrorParameter)
                << '\n';
        else if (!report.commError)
            out << tr("Communication error register (%1): %2, not a known code.")
                       .arg(report.commErrorParameter, hexCode(*report.commErrorCode))
                << '\n';
        else
            out << tr("Communication error register (%1): %2 %3\n  Cause: %4\n  Remedy: %5")
                       .arg(report.commErrorParameter, report.commError->panel,
                            report.commError->name, report.commError->cause,
                            report.commError->remedy)
                << '\n';
    }
}

} // namespace

QString AlarmsCommand::summary() const
{
    return tr("Show alarm and warning histories with causes and remedies; reset, erase");
}

QList<QCommandLineOption> AlarmsCommand::options() const
{
    return {
        {QStringLiteral("reset"),
         tr("Send the alarm reset command, then tell whether the alarm is cleared or needs a power "
            "cycle (needs --yes; exit 4 when it stays active).")},
        {QStringLiteral("clear-records"), tr("Erase the alarm and warning records (needs --yes).")},
        {QStringLiteral("yes"), tr("Confirm --reset and --clear-records.")},
    };
}

int AlarmsCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& out = context.out();
    QTextStream& err = context.err();
    QString error;
    const auto ids = args.size() == 1 ? CliContext::parseIds(args.first(), &error) : std::nullopt;
    if (!ids || ids->size() != 1) {
        err << tr("error: usage: %1 (one machine number)").arg(synopsis()) << Qt::endl;
        return ExitUsage;
    }
    const bool reset = context.parser().isSet(QStringLiteral("reset"));
    const bool clear = context.parser().isSet(QStringLiteral("clear-records"));
    const int slave = ids->first();
    DeviceSession* session = context.session(slave, &error);
    if (!session) {
        err << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitCommunication;
    }
    AlarmHistory history(session);
    const QString family = session->profile().family;
    if (!history.supported()) {
        err << tr("error: machine number %1 (%2) keeps no alarm or warning records")
                   .arg(slave)
                   .arg(family)
            << Qt::endl;
        return ExitUsage;
    }
    if ((reset && !history.canReset()) || (clear && !history.canClear())) {
        err << tr("error: %1 drives have no %2 command")
                   .arg(family,
                        reset && !history.canReset() ? tr("alarm reset") : tr("record erase"))
            << Qt::endl;
        return ExitUsage;
    }
    // Drives in the target's communication group execute a reset or erase too, silently.
    GroupCheck group(context);
    if ((reset || clear) && context.parser().isSet(QStringLiteral("yes"))) {
        if (const int refused = group.before(slave, true, ExitUsage); refused != ExitOk)
            return refused;
    }
    if ((reset || clear) && !context.parser().isSet(QStringLiteral("yes"))) {
        err << tr("These change machine number %1; add --yes to send them:").arg(slave) << '\n';
        if (reset)
            for (const QString& w : history.resetPlan())
                err << "  " << w << ' '
                    << tr("— clears the active alarm if its cause is gone and it is not one that "
                          "only a power cycle clears")
                    << '\n';
        if (clear)
            for (const QString& w : history.clearPlan())
                err << "  " << w << '\n';
        err.flush();
        group.before(slave, false, ExitUsage); // names the drives of its group, if any
        return ExitUsage;
    }

    AlarmHistory::Report report;
    if (!context.wait([&](std::function<void()> finish) {
            history.read([&report, finish](const AlarmHistory::Report& r) {
                report = r;
                finish();
            });
        }))
        return ExitInterrupted;
    QJsonObject json = reportJson(report);
    json.insert(QStringLiteral("slave"), slave);
    json.insert(QStringLiteral("family"), family);
    if (!context.json()) {
        const ProfileVariant* variant = session->profile().variant(session->variant());
        const QString model = variant ? variant->model : family;
        out << tr("Machine number %1 (%2)")
                   .arg(slave)
                   .arg(DriveName::nameAndModel(session->machineName(), model))
            << '\n';
        printReport(out, report);
    }
    int code = report.ok ? ExitOk : ExitCommunication;

    if (reset) {
        AlarmHistory::ResetOutcome r;
        if (!context.wait([&](std::function<void()> finish) {
                history.reset([&r, finish](const AlarmHistory::ResetOutcome& o) {
                    r = o;
                    finish();
                });
            }))
            return ExitInterrupted;
        QJsonObject o{{QStringLiteral("sent"), r.sent},
                      {QStringLiteral("accepted"), r.ok},
                      {QStringLiteral("wasActive"), r.wasActive},
                      {QStringLiteral("powerCycleNeeded"), r.powerCycleNeeded},
                      {QStringLiteral("explanation"), r.explanation}};
        if (r.stillActive)
            o.insert(QStringLiteral("stillActive"), *r.stillActive);
        if (!r.error.isEmpty())
            o.insert(QStringLiteral("error"), r.error);
        json.insert(QStringLiteral("reset"), o);
        if (!context.json())
            out << '\n' << tr("Alarm reset: %1").arg(r.explanation) << '\n';
        if (r.stillActive.value_or(false))
            code = std::max<int>(code, ExitMismatch);
        else if (!r.ok || !r.stillActive)
            code = code == ExitOk ? ExitCommunication : code;
    }
    if (clear) {
        AlarmHistory::ClearOutcome c;
        if (!context.wait([&](std::function<void()> finish) {
                history.clearRecords([&c, finish](const AlarmHistory::ClearOutcome& o) {
                    c = o;
                    finish();
                });
            }))
            return ExitInterrupted;
        json.insert(QStringLiteral("cleared"),
                    QJsonObject{{QStringLiteral("tables"), QJsonArray::fromStringList(c.cleared)},
                                {QStringLiteral("records"), c.erasedRecords},
                                {QStringLiteral("verified"), c.verified},
                                {QStringLiteral("errors"), QJsonArray::fromStringList(c.errors)}});
        if (!context.json()) {
            out << '\n';
            if (!c.cleared.isEmpty())
                out << tr("Erased: %1 (%2 records); %3")
                           .arg(c.cleared.join(QStringLiteral(", ")))
                           .arg(c.erasedRecords)
                           .arg(c.verified ? tr("read back empty.")
                                           : tr("NOT empty when read back."))
                    << '\n';
            for (const QString& e : c.errors)
                out << tr("Erasing failed: %1").arg(e) << '\n';
        }
        if (!c.errors.isEmpty())
            code = code == ExitOk ? ExitCommunication : code;
        else if (!c.verified)
            code = std::max<int>(code, ExitMismatch);
    }
    if (context.json())
        out << QJsonDocument(json).toJson(QJsonDocument::Indented);
    return code;
}

} // namespace opentop
