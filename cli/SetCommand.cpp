#include "cli/SetCommand.h"

#include "cli/CliContext.h"
#include "cli/GroupCheck.h"
#include "cli/SetRaw.h"
#include "cli/TextTable.h"
#include "model/files/RestorePlan.h"
#include "model/io/DisplayText.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "model/session/ParameterInitialiser.h"
#include "model/session/SerialLock.h"
#include "model/session/SettingsWrite.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::SetCommand", text);
}

// The problems that end a set before anything is sent, then "nothing was written".
void printRefusal(CliContext& context, const QStringList& problems)
{
    for (const QString& p : problems)
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(p)) << Qt::endl;
    context.err() << tr("nothing was written") << Qt::endl;
}

} // namespace

QString SetCommand::summary() const
{
    return tr("Write parameters by name, validated, read back and verified");
}

QList<QCommandLineOption> SetCommand::options() const
{
    return {
        {QStringLiteral("yes"),
         tr("Confirm commands that move a motor, reset, erase, initialise or store, and "
            "setting the serial configuration lock.")},
        {QStringLiteral("raw"),
         tr("Write registers by address: ADDR=VALUE (repeatable; VALUE,VALUE... with --fc 16)."),
         tr("ADDR=VALUE")},
        {QStringLiteral("fc"), tr("Function code for --raw writes: 6 (default) or 16."), tr("FC")}};
}

int SetCommand::run(CliContext& context, const QStringList& args)
{
    QString error;
    const auto ids = args.isEmpty() ? std::nullopt : CliContext::parseIds(args.first(), &error);
    const bool raw = context.parser().isSet(QStringLiteral("raw"));
    if (!ids || ids->size() != 1 || (args.size() < 2) != raw) {
        context.err() << tr("error: usage: set ID NAME=VALUE... (e.g. set 1 spno2.accel=2.5), or "
                            "set ID --raw ADDR=VALUE")
                      << Qt::endl;
        return ExitUsage;
    }
    const int slave = ids->first();
    if (raw)
        return SetRaw::run(context, slave, context.parser().values(QStringLiteral("raw")));
    QStringList given;
    for (const QString& arg : args.mid(1)) {
        const int eq = arg.indexOf(QLatin1Char('='));
        if (eq <= 0) {
            context.err() << tr("error: \"%1\" is not NAME=VALUE").arg(arg) << Qt::endl;
            return ExitUsage;
        }
        given << arg;
    }
    DeviceSession* session = context.session(slave, &error);
    if (!session) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitCommunication;
    }
    const bool confirmed = context.parser().isSet(QStringLiteral("yes"));
    SettingsWrite set(session, confirmed);
    for (const QString& arg : given) {
        const int eq = arg.indexOf(QLatin1Char('='));
        if (const QString twice = set.add(arg.left(eq).trimmed(), arg.mid(eq + 1).trimmed());
            !twice.isEmpty()) {
            context.err() << tr("error: %1").arg(DisplayText::escapedLines(twice)) << Qt::endl;
            return ExitUsage;
        }
    }
    SettingsWrite::Plan plan;
    if (!context.wait([&](std::function<void()> finish) {
            set.prepare([&plan, finish](const SettingsWrite::Plan& p) {
                plan = p;
                finish();
            });
        }))
        return ExitInterrupted;
    for (const QString& c : plan.consequences)
        context.err() << tr("warning: %1").arg(DisplayText::escapedLines(c)) << Qt::endl;
    if (plan.refusal == SettingsWrite::Refusal::Communication) {
        context.err()
            << tr("error: %1").arg(DisplayText::escapedLines(plan.problems.join(QLatin1Char(' '))))
            << Qt::endl;
        return ExitCommunication;
    }
    if (plan.refusal != SettingsWrite::Refusal::None) {
        printRefusal(context, plan.problems);
        return ExitInvalid;
    }
    for (const QString& w : plan.warnings + plan.advice)
        context.err() << tr("warning: %1").arg(DisplayText::escapedLines(w)) << Qt::endl;
    // Drives in the target's communication group execute the writes too, silently: each must
    // allow every value by its own profile and variant before anything is sent.
    GroupCheck group(context);
    if (const int refused = group.read(slave); refused != ExitOk)
        return refused;
    QStringList childProblems;
    bool childUnread = false;
    if (!context.wait([&](std::function<void()> finish) {
            set.checkReached([&, finish](const QStringList& problems, bool communication) {
                childProblems = problems;
                childUnread = communication;
                finish();
            });
        }))
        return ExitInterrupted;
    if (!childProblems.isEmpty()) {
        printRefusal(context, childProblems);
        return childUnread ? ExitCommunication : ExitInvalid;
    }
    if (const int refused = group.confirm(slave, confirmed, ExitInvalid); refused != ExitOk)
        return refused;
    if (!context.wait([&](std::function<void()> finish) { set.write(finish); }))
        set.cancel(); // Ctrl+C: nothing more is sent
    int code = set.cancelled() ? ExitInterrupted : ExitOk;
    for (const SettingsWrite::Item& a : set.items()) {
        if (!a.outcome.ok && code == ExitOk)
            code = a.outcome.mismatch ? ExitMismatch : ExitCommunication;
    }
    if (set.initialisationSent()) {
        const ParameterInitialiser::Plan& init = *set.initialisation();
        for (const QString& step : init.afterwards)
            context.err() << tr("next: %1").arg(step) << Qt::endl;
        if (init.reconnectBaud > 0)
            context.err() << tr("next: opentop-cli --baud %1 --parity %2 --stop-bits %3 ... "
                                "(the factory line settings)")
                                 .arg(init.reconnectBaud)
                                 .arg(QLatin1Char(init.reconnectParity))
                                 .arg(init.reconnectStopBits)
                          << Qt::endl;
    }
    const Profile& profile = session->profile();
    const QVector<SettingsWrite::Item>& assignments = set.items();
    const ValueContext valueContext = session->context();
    QStringList written;
    for (const SettingsWrite::Item& a : assignments)
        if (a.outcome.sent)
            written << a.name;
    // What the writes themselves read back from the children, compared with what was written.
    QVector<GroupCheck::ChildValue> childValues;
    for (const SettingsWrite::Item& a : assignments)
        childValues += GroupCheck::fromOutcome(a.name, a.outcome.reached);
    if (context.json()) {
        QJsonArray results;
        for (const SettingsWrite::Item& a : assignments) {
            QJsonObject r{{QStringLiteral("name"), a.name},
                          {QStringLiteral("requested"), a.text},
                          {QStringLiteral("ok"), a.outcome.ok},
                          {QStringLiteral("verified"), a.outcome.verified}};
            if (a.outcome.value.valid)
                r.insert(QStringLiteral("text"),
                         ValueCodec::format(*a.meta, a.outcome.value, valueContext));
            if (!a.outcome.error.isEmpty())
                r.insert(QStringLiteral("error"), a.outcome.error);
            if (!a.outcome.warning.isEmpty())
                r.insert(QStringLiteral("warning"), a.outcome.warning);
            if (a.outcome.unconfirmed)
                r.insert(QStringLiteral("notConfirmed"), true);
            if (!a.outcome.notVerified.isEmpty())
                r.insert(QStringLiteral("notVerified"), a.outcome.notVerified);
            if (!a.outcome.explanation.isEmpty())
                r.insert(QStringLiteral("explanation"), a.outcome.explanation);
            results.append(r);
        }
        QJsonObject json{{QStringLiteral("slave"), slave}, {QStringLiteral("results"), results}};
        if (!group.children().isEmpty())
            json.insert(QStringLiteral("group"), GroupCheck::toJson(childValues));
        context.out() << QJsonDocument(json).toJson(QJsonDocument::Indented);
    } else {
        TextTable table({tr("Parameter"), tr("Value"), tr("Result")});
        for (const SettingsWrite::Item& a : assignments) {
            const QString value = a.outcome.value.valid
                                      ? ValueCodec::format(*a.meta, a.outcome.value, valueContext)
                                      : a.text;
            const QString result =
                a.outcome.ok ? (a.outcome.verified ? tr("written, verified")
                                : !a.outcome.notVerified.isEmpty()
                                    ? tr("written, not verified: %1").arg(a.outcome.notVerified)
                                    : tr("written (command, not readable)"))
                : a.outcome.unconfirmed
                    ? tr("not confirmed (%1): the drive may or may not hold it; \"get\" reads "
                         "it back")
                          .arg(a.outcome.error)
                    : a.outcome.error;
            table.addRow({a.name, value, result});
        }
        table.print(context.out());
        group.print(childValues);
        // What a drive's error code means and what to do, under the table it belongs to.
        for (const SettingsWrite::Item& a : assignments)
            if (!a.outcome.explanation.isEmpty())
                context.err() << tr("%1: %2").arg(a.name, a.outcome.explanation) << Qt::endl;
    }
    // The line settings change at the drive's next power-up (the same answer as the profile's
    // help, the restore and the simulator: errata DC-18).
    for (const SettingsWrite::Item& a : assignments) {
        if (a.outcome.ok && RestorePlan::isCommunicationSetting(profile, *a.meta) &&
            !SerialLock::locks(profile, *a.meta, 1))
            context.err() << tr("note: the drive uses %1 from its next power-up on: switch the "
                                "drive off and on, then connect with the new "
                                "setting (--baud, --parity)")
                                 .arg(a.name)
                          << Qt::endl;
    }
    return code;
}

} // namespace opentop
