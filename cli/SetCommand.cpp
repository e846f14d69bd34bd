#include "cli/SetCommand.h"

#include "cli/CliContext.h"
#include "cli/GroupCheck.h"
#include "cli/SetRaw.h"
#include "cli/TextTable.h"
#include "model/files/RestorePlan.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/RunningData.h"
#include "model/profile/ValueCodec.h"
#include "model/profile/WriteOrder.h"
#include "model/session/DependentValues.h"
#include "model/session/DeviceSession.h"
#include "model/session/ParameterInitialiser.h"
#include "model/session/ReachedDrives.h"
#include "model/session/SerialLock.h"
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

struct Assignment
{
    QString name;
    QString text;
    const ParameterMeta* meta = nullptr;
    DeviceSession::Outcome outcome;
    QVector<quint16> registers; // as validated, before anything is sent
};

// The drives of the target's communication group execute the writes too: each must allow every
// value by its own profile, variant and values (ReachedDrives), or nothing is sent.
int checkChildren(CliContext& context, DeviceSession* session,
                  const QVector<Assignment>& assignments)
{
    const ReachedDrives reached(session, session->reachedDrives());
    if (reached.isEmpty())
        return ExitOk;
    QVector<const ParameterMeta*> metas;
    QStringList names;
    for (const Assignment& a : assignments) {
        metas << a.meta;
        names << a.name;
    }
    QString problem;
    if (!context.wait([&](std::function<void()> finish) {
            reached.ensureKnown(metas, names, [&problem, finish](const QString& p) {
                problem = p;
                finish();
            });
        }))
        return ExitInterrupted;
    QStringList problems;
    if (!problem.isEmpty())
        problems << problem;
    for (const Assignment& a : assignments) {
        const QString refused =
            problem.isEmpty() ? reached.problem(*a.meta, a.registers, names, true) : QString();
        if (!refused.isEmpty())
            problems << refused;
    }
    if (problems.isEmpty())
        return ExitOk;
    for (const QString& p : problems)
        context.err() << QCoreApplication::translate("opentop::SetCommand", "error: %1").arg(p)
                      << Qt::endl;
    context.err() << QCoreApplication::translate("opentop::SetCommand", "nothing was written")
                  << Qt::endl;
    return problem.isEmpty() ? ExitInvalid : ExitCommunication;
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
    QVector<Assignment> assignments;
    for (const QString& arg : args.mid(1)) {
        const int eq = arg.indexOf(QLatin1Char('='));
        if (eq <= 0) {
            context.err() << tr("error: \"%1\" is not NAME=VALUE").arg(arg) << Qt::endl;
            return ExitUsage;
        }
        const QString name = arg.left(eq).trimmed();
        for (const Assignment& a : assignments) {
            if (a.name == name) {
                // Which one would the drive keep? Neither is written.
                context.err() << tr("error: %1 is given twice (%2=%3 and %4); give each setting "
                                    "once; nothing written")
                                     .arg(name, name, a.text, arg)
                              << Qt::endl;
                return ExitUsage;
            }
        }
        assignments.append({name, arg.mid(eq + 1).trimmed(), nullptr, {}, {}});
    }
    DeviceSession* session = context.session(slave, &error);
    if (!session) {
        context.err() << tr("error: %1").arg(error) << Qt::endl;
        return ExitCommunication;
    }
    const Profile& profile = session->profile();
    const bool confirmed = context.parser().isSet(QStringLiteral("yes"));
    QStringList problems;
    QStringList controlling;
    for (Assignment& a : assignments) {
        a.meta = profile.parameter(a.name);
        if (!a.meta)
            problems << tr("%1 has no parameter \"%2\"; see \"opentop-cli params --family %1\"")
                            .arg(profile.family, a.name);
        else if (!a.meta->isWritable())
            problems << tr("%1 is read-only").arg(a.name);
        else if (!a.meta->safety.isEmpty() && !confirmed)
            problems << tr("%1 is a %2 command; add --yes to send it").arg(a.name, a.meta->safety);
        else {
            for (const QString& c : a.meta->controllingParameters())
                if (!session->hasCached(c) && !controlling.contains(c))
                    controlling << c;
            // The settings that depend on this one are checked against its new value.
            for (const QString& d : DependentValues::of(profile, *a.meta))
                if (!session->hasCached(d) && !controlling.contains(d))
                    controlling << d;
            // The deceleration advice weighs an SPno's speed against its deceleration.
            QString field;
            if (const int spno = RunningData::spnoOf(a.name, &field); spno > 0) {
                for (const char* other : {"speed", "decel"}) {
                    const QString n = RunningData::parameter(profile, spno, QLatin1String(other));
                    if (!n.isEmpty() && n != a.name && !session->hasCached(n) &&
                        !controlling.contains(n) && profile.parameter(n)->isReadable())
                        controlling << n;
                }
            }
        }
    }
    // Parameter initialisation resets the line settings and control priority too: the
    // consequences are said before anything is sent (also as the reason to add --yes), and what
    // to do afterwards once it was sent.
    std::optional<ParameterInitialiser::Plan> initPlan;
    const ParameterMeta* initMeta =
        RoleEvaluator::parameter(profile, QStringLiteral("parameterInit"));
    if (initMeta &&
        std::any_of(assignments.begin(), assignments.end(),
                    [initMeta](const Assignment& a) { return a.name == initMeta->name; })) {
        ParameterInitialiser init(session);
        ParameterInitialiser::Plan plan;
        context.wait([&](std::function<void()> finish) {
            init.check([&plan, finish](const ParameterInitialiser::Plan& p) {
                plan = p;
                finish();
            });
        });
        for (const QString& c : plan.consequences)
            context.err() << tr("warning: %1").arg(c) << Qt::endl;
        if (!plan.refusal.isEmpty())
            problems << plan.refusal;
        initPlan = plan;
    }
    // What allowed values depend on must be known before anything can be validated.
    if (problems.isEmpty() && !controlling.isEmpty()) {
        DeviceSession::ReadManyOutcome read;
        context.wait([&](std::function<void()> finish) {
            session->readMany(controlling,
                              [&read, finish](const DeviceSession::ReadManyOutcome& o) {
                                  read = o;
                                  finish();
                              });
        });
        if (read.failed > 0) {
            context.err() << tr("error: cannot read %1 to check the values; nothing written")
                                 .arg(controlling.join(QStringLiteral(", ")))
                          << Qt::endl;
            return ExitCommunication;
        }
    }
    // Writes that others depend on go first; each value is validated against what the drive
    // will hold when it is written.
    {
        QStringList given;
        for (const Assignment& a : assignments)
            given << a.name;
        const QStringList order = WriteOrder::of(session->profile(), given);
        std::sort(assignments.begin(), assignments.end(),
                  [&order](const Assignment& x, const Assignment& y) {
                      return order.indexOf(x.name) < order.indexOf(y.name);
                  });
    }
    if (problems.isEmpty()) {
        QHash<QString, qint64> pending;
        ValueContext overlay = session->context();
        const auto base = overlay.parameterRaw;
        overlay.parameterRaw = [&pending, base](const QString& n) -> std::optional<qint64> {
            return pending.contains(n) ? std::optional<qint64>(pending.value(n)) : base(n);
        };
        QStringList names;
        for (const Assignment& a : assignments)
            names << a.name;
        QStringList warnings; // allowed, but outside the recommended range, or a serial lock
        for (Assignment& a : assignments) {
            const ValueCodec::Encoded e = ValueCodec::encodeText(*a.meta, a.text, overlay);
            if (!e.ok) {
                problems << e.error;
                continue;
            }
            a.registers = e.registers;
            if (!e.warning.isEmpty())
                warnings << e.warning;
            // It can shut this program out of the drive's configuration: only on request.
            const QString lock = SerialLock::warning(profile, *a.meta, qint64(e.raw), overlay);
            if (!lock.isEmpty() && !confirmed)
                problems << lock + QLatin1Char(' ') + tr("Add --yes to set it.");
            else if (!lock.isEmpty())
                warnings << lock;
            // The same rule DeviceSession::write applies, before anything is sent.
            const QString left =
                DependentValues::problem(profile, *a.meta, qint64(e.raw), overlay, names);
            if (!left.isEmpty())
                problems << left;
            pending.insert(a.name, qint64(e.raw));
        }
        if (problems.isEmpty()) {
            for (const QString& w : warnings)
                context.err() << tr("warning: %1").arg(w) << Qt::endl;
        }
        // Advice, not a refusal: the manual's deceleration rule for the values as written.
        QStringList advised;
        for (const Assignment& a : assignments) {
            if (!problems.isEmpty() || !pending.contains(a.name))
                continue;
            const QString w =
                RunningData::warningFor(profile, a.name, pending.value(a.name), overlay);
            if (!w.isEmpty() && !advised.contains(w)) {
                advised << w;
                context.err() << tr("warning: %1").arg(w) << Qt::endl;
            }
        }
    }
    if (!problems.isEmpty()) {
        for (const QString& p : problems)
            context.err() << tr("error: %1").arg(p) << Qt::endl;
        context.err() << tr("nothing was written") << Qt::endl;
        return ExitInvalid;
    }
    // Drives in the target's communication group execute the writes too, silently: each must
    // allow every value by its own profile and variant before anything is sent.
    GroupCheck group(context);
    if (const int refused = group.read(slave); refused != ExitOk)
        return refused;
    if (const int refused = checkChildren(context, session, assignments); refused != ExitOk)
        return refused;
    if (const int refused = group.confirm(slave, confirmed, ExitInvalid); refused != ExitOk)
        return refused;
    int code = ExitOk;
    bool stopped = false;
    for (int i = 0; i < assignments.size(); ++i) {
        Assignment& a = assignments[i];
        DeviceSession::WriteOptions options;
        options.explicitCommand = confirmed;
        for (int later = i + 1; later < assignments.size(); ++later)
            options.companions << assignments.at(later).name;
        if (stopped || !context.wait([&](std::function<void()> finish) {
                session->write(a.name, a.text, options,
                               [&a, finish](const DeviceSession::Outcome& o) {
                                   a.outcome = o;
                                   finish();
                               });
            })) {
            stopped = true;
            a.outcome.error = tr("not written (interrupted)");
            code = ExitInterrupted;
            continue;
        }
        if (!a.outcome.ok && code == ExitOk)
            code = a.outcome.mismatch ? ExitMismatch : ExitCommunication;
    }
    if (initPlan) {
        const bool sent = std::any_of(assignments.begin(), assignments.end(), [&](const auto& a) {
            return a.name == initMeta->name && a.outcome.ok;
        });
        if (sent) {
            for (const QString& step : initPlan->afterwards)
                context.err() << tr("next: %1").arg(step) << Qt::endl;
            if (initPlan->reconnectBaud > 0)
                context.err() << tr("next: opentop-cli --baud %1 --parity %2 --stop-bits %3 ... "
                                    "(the factory line settings)")
                                     .arg(initPlan->reconnectBaud)
                                     .arg(QLatin1Char(initPlan->reconnectParity))
                                     .arg(initPlan->reconnectStopBits)
                              << Qt::endl;
        }
    }
    const ValueContext valueContext = session->context();
    QStringList written;
    for (const Assignment& a : assignments)
        if (a.outcome.sent)
            written << a.name;
    // What the writes themselves read back from the children, compared with what was written.
    QVector<GroupCheck::ChildValue> childValues;
    for (const Assignment& a : assignments)
        childValues += GroupCheck::fromOutcome(a.name, a.outcome.reached);
    if (context.json()) {
        QJsonArray results;
        for (const Assignment& a : assignments) {
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
        for (const Assignment& a : assignments) {
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
        for (const Assignment& a : assignments)
            if (!a.outcome.explanation.isEmpty())
                context.err() << tr("%1: %2").arg(a.name, a.outcome.explanation) << Qt::endl;
    }
    // The line settings change at the drive's next power-up (the same answer as the profile's
    // help, the restore and the simulator: errata DC-18).
    for (const Assignment& a : assignments) {
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
