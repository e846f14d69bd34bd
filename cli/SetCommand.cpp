#include "SetCommand.h"

#include "CliContext.h"
#include "GroupCheck.h"
#include "ModbusClient.h"
#include "TextTable.h"
#include "files/RestorePlan.h"
#include "profile/RoleEvaluator.h"
#include "profile/ValueCodec.h"
#include "run/RunningData.h"
#include "session/DependentValues.h"
#include "session/DeviceSession.h"
#include "session/ParameterInitialiser.h"
#include "session/SerialLock.h"

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
};

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
        return runRaw(context, slave, context.parser().values(QStringLiteral("raw")));
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
        assignments.append({name, arg.mid(eq + 1).trimmed(), nullptr, {}});
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
    std::stable_sort(
        assignments.begin(), assignments.end(), [](const Assignment& x, const Assignment& y) {
            return x.meta && y.meta && y.meta->controllingParameters().contains(x.name);
        });
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
        for (const Assignment& a : assignments) {
            const ValueCodec::Encoded e = ValueCodec::encodeText(*a.meta, a.text, overlay);
            if (!e.ok) {
                problems << e.error;
                continue;
            }
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
    // Drives in the target's communication group execute the writes too, silently.
    GroupCheck group(context);
    if (const int refused = group.before(slave, confirmed, ExitInvalid); refused != ExitOk)
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
    const QVector<GroupCheck::ChildValue> childValues =
        written.isEmpty() ? QVector<GroupCheck::ChildValue>() : group.readChildren(written);
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

int SetCommand::runRaw(CliContext& context, int slave, const QStringList& assignments)
{
    const int fc = context.parser().isSet(QStringLiteral("fc"))
                       ? context.parser().value(QStringLiteral("fc")).toInt()
                       : 6;
    if (fc != 6 && fc != 16) {
        context.err() << tr("error: --fc for raw writes is 6 or 16") << Qt::endl;
        return ExitUsage;
    }
    auto number = [](const QString& text, bool* ok) {
        const QString t = text.trimmed();
        return t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? t.mid(2).toUInt(ok, 16)
                                                                      : t.toUInt(ok);
    };
    struct RawWrite
    {
        quint16 address;
        QVector<quint16> values;
    };
    QVector<RawWrite> writes;
    for (const QString& a : assignments) {
        const int eq = a.indexOf(QLatin1Char('='));
        bool ok = eq > 0;
        const uint address = ok ? number(a.left(eq), &ok) : 0;
        RawWrite w{quint16(address), {}};
        for (const QString& v : a.mid(eq + 1).split(QLatin1Char(','))) {
            bool okValue = false;
            const uint value = number(v, &okValue);
            ok = ok && okValue && value <= 0xFFFF;
            w.values << quint16(value);
        }
        if (!ok || address > 0xFFFF || (fc == 6 && w.values.size() != 1) || w.values.size() > 123) {
            context.err() << tr("error: \"%1\" is not ADDR=VALUE (0x.. or decimal, 0–65535; "
                                "several values, comma separated, only with --fc 16)")
                                 .arg(a)
                          << Qt::endl;
            return ExitUsage;
        }
        writes << w;
    }
    // Raw writes are for service work, but they still never bypass the profile's checks or the
    // confirmation that commands need.
    QString error;
    DeviceSession* session = context.session(slave, &error);
    const bool confirmed = context.parser().isSet(QStringLiteral("yes"));
    for (const RawWrite& w : writes) {
        const ParameterMeta* meta =
            session ? session->profile().parameterAt(quint8(fc), w.address) : nullptr;
        if (!meta && !confirmed) {
            context.err() << tr("error: 0x%1 is not a register the profile knows; add --yes to "
                                "write it anyway; nothing was written")
                                 .arg(w.address, 4, 16, QLatin1Char('0'))
                          << Qt::endl;
            return ExitInvalid;
        }
        if (meta && w.address == meta->address && w.values.size() == meta->registerCount) {
            const QString problem = ValueCodec::checkRaw(
                *meta, ValueCodec::registersToRaw(*meta, w.values), session->context());
            if (!problem.isEmpty() || (!meta->safety.isEmpty() && !confirmed)) {
                context.err() << tr("error: %1; nothing was written")
                                     .arg(problem.isEmpty() ? tr("%1 is a %2 command; add --yes")
                                                                  .arg(meta->name, meta->safety)
                                                            : problem)
                              << Qt::endl;
                return ExitInvalid;
            }
        } else if (meta && !confirmed) {
            context.err() << tr("error: the write covers part of %1; add --yes to write it anyway; "
                                "nothing was written")
                                 .arg(meta->name)
                          << Qt::endl;
            return ExitInvalid;
        }
    }
    if (!context.connectBus())
        return ExitCommunication;
    GroupCheck group(context);
    if (const int refused = group.before(slave, confirmed, ExitInvalid); refused != ExitOk)
        return refused;
    QStringList known; // what the children are read back as, where the profile names it
    for (const RawWrite& w : writes)
        if (const ParameterMeta* meta =
                session ? session->profile().parameterAt(quint8(fc), w.address) : nullptr)
            if (meta->isReadable() && !known.contains(meta->name))
                known << meta->name;
    int code = ExitOk;
    TextTable table({tr("Address"), tr("Written"), tr("Result")});
    for (const RawWrite& w : writes) {
        const ModbusRequest request =
            fc == 6 ? ModbusRequest::writeSingle(quint8(slave), w.address, w.values.first())
                    : ModbusRequest::writeMultiple(quint8(slave), w.address, w.values);
        ModbusResult result;
        if (!context.wait([&](std::function<void()> finish) {
                context.client()->submit(request, &context,
                                         [&result, finish](const ModbusResult& r) {
                                             result = r;
                                             finish();
                                         });
            }))
            return ExitInterrupted;
        QStringList hex;
        for (quint16 v : w.values)
            hex << QStringLiteral("%1").arg(v, 4, 16, QLatin1Char('0')).toUpper();
        const QString where = QStringLiteral("0x%1").arg(w.address, 4, 16, QLatin1Char('0'));
        if (!result.ok()) {
            table.addRow({where, hex.join(QLatin1Char(' ')), result.errorText()});
            code = ExitCommunication;
            continue;
        }
        // Read back where the address is a readable holding register.
        const ModbusRequest readBack =
            ModbusRequest::readHolding(quint8(slave), w.address, quint16(w.values.size()));
        ModbusResult back;
        context.wait([&](std::function<void()> finish) {
            context.client()->submit(readBack, &context, [&back, finish](const ModbusResult& r) {
                back = r;
                finish();
            });
        });
        QString verdict = tr("written");
        if (back.ok() && back.registers == w.values) {
            verdict = tr("written, verified");
        } else if (back.ok()) {
            verdict = tr("written, but reads back differently");
            code = ExitMismatch;
        } else {
            verdict = tr("written (not readable back: %1)").arg(back.errorText());
        }
        table.addRow({where, hex.join(QLatin1Char(' ')), verdict});
    }
    table.print(context.out());
    if (!known.isEmpty())
        group.print(group.readChildren(known));
    else if (!group.children().isEmpty())
        context.out() << tr("Also written to %1 (communication group); not read back: no "
                            "parameter of the profile")
                             .arg(BusGroups::listText(group.children()))
                      << Qt::endl;
    return code;
}

} // namespace opentop
