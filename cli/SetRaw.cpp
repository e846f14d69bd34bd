#include "cli/SetRaw.h"

#include "cli/CliContext.h"
#include "cli/GroupCheck.h"
#include "cli/TextTable.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "model/session/ReachedDrives.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::SetRaw", text);
}

} // namespace

int SetRaw::run(CliContext& context, int slave, const QStringList& assignments)
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
    if (const int refused = group.read(slave); refused != ExitOk)
        return refused;
    // The children check what the profile names as it does for the target, before sending.
    const ReachedDrives reached(session,
                                session ? session->reachedDrives() : QVector<DeviceSession*>());
    QVector<const ParameterMeta*> checked;
    QHash<QString, QVector<quint16>> expected; // what the children must hold afterwards
    for (const RawWrite& w : writes) {
        const ParameterMeta* meta =
            session ? session->profile().parameterAt(quint8(fc), w.address) : nullptr;
        if (meta && w.address == meta->address && w.values.size() == meta->registerCount) {
            checked << meta;
            expected.insert(meta->name, w.values);
        }
    }
    if (!reached.isEmpty() && !checked.isEmpty()) {
        QString problem;
        if (!context.wait([&](std::function<void()> finish) {
                reached.ensureKnown(checked, {}, [&problem, finish](const QString& p) {
                    problem = p;
                    finish();
                });
            }))
            return ExitInterrupted;
        for (int i = 0; i < checked.size() && problem.isEmpty(); ++i)
            problem = reached.problem(*checked[i], expected.value(checked[i]->name), {}, false);
        if (!problem.isEmpty()) {
            context.err() << tr("error: %1; nothing was written").arg(problem) << Qt::endl;
            return ExitInvalid;
        }
    }
    if (const int refused = group.confirm(slave, confirmed, ExitInvalid); refused != ExitOk)
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
    if (!known.isEmpty()) {
        const QVector<GroupCheck::ChildValue> children = group.readChildren(known, expected);
        group.print(children);
        for (const GroupCheck::ChildValue& c : children)
            if (c.differs)
                code = ExitMismatch; // a child holds another value: not verified
    } else if (!group.children().isEmpty())
        context.out() << tr("Also written to %1 (communication group); not read back: no "
                            "parameter of the profile")
                             .arg(BusGroups::listText(group.children()))
                      << Qt::endl;
    return code;
}

} // namespace opentop
