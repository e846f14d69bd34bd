#include "cli/GetCommand.h"

#include "cli/CliContext.h"
#include "cli/TextTable.h"
#include "model/io/DisplayText.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::GetCommand", text);
}

QString hexRegisters(const QVector<quint16>& regs)
{
    QStringList parts;
    for (quint16 r : regs)
        parts << QStringLiteral("%1").arg(r, 4, 16, QLatin1Char('0')).toUpper();
    return parts.join(QLatin1Char(' '));
}

QJsonArray registersJson(const QVector<quint16>& regs)
{
    QJsonArray a;
    for (quint16 r : regs)
        a.append(int(r));
    return a;
}

} // namespace

QString GetCommand::summary() const
{
    return tr("Read parameters by name in engineering units (or registers with --raw)");
}

QList<QCommandLineOption> GetCommand::options() const
{
    return {
        {QStringLiteral("group"), tr("Read every parameter of a group (see params)."), tr("GROUP")},
        {QStringLiteral("all"), tr("Read every readable parameter.")},
        {QStringLiteral("raw"),
         tr("Read registers by address: ADDR or ADDR:COUNT (0x.. or decimal)."), tr("ADDR")},
        {QStringLiteral("fc"),
         tr("Function code for --raw: 3 (holding) or 4 (input) to read, 6 or 16 to write."),
         tr("FC")}};
}

int GetCommand::run(CliContext& context, const QStringList& args)
{
    QString error;
    const auto ids = args.isEmpty() ? std::nullopt : CliContext::parseIds(args.first(), &error);
    if (!ids || ids->size() != 1) {
        context.err() << tr("error: give one machine number first: get ID NAME...") << Qt::endl;
        return ExitUsage;
    }
    const int slave = ids->first();
    const QCommandLineParser& p = context.parser();
    const int selectors = int(args.size() > 1) + int(p.isSet(QStringLiteral("group"))) +
                          int(p.isSet(QStringLiteral("all"))) + int(p.isSet(QStringLiteral("raw")));
    if (selectors != 1) {
        context.err() << tr("error: name parameters, or give exactly one of --group, --all, --raw")
                      << Qt::endl;
        return ExitUsage;
    }
    if (p.isSet(QStringLiteral("raw")))
        return runRaw(context, slave);
    DeviceSession* session = context.session(slave, &error);
    if (!session) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitCommunication;
    }
    const Profile& profile = session->profile();
    QStringList names = args.mid(1);
    if (p.isSet(QStringLiteral("group"))) {
        const QString group = p.value(QStringLiteral("group"));
        if (!profile.group(group)) {
            QStringList known;
            for (const ProfileGroup& g : profile.groups)
                known << g.id;
            context.err() << tr("error: %1 has no group \"%2\"; groups: %3")
                                 .arg(profile.family, group, known.join(QStringLiteral(", ")))
                          << Qt::endl;
            return ExitUsage;
        }
        for (const ParameterMeta* m : profile.parametersInGroup(group)) {
            if (m->isReadable() && m->kind != QLatin1String("reserved"))
                names << m->name;
        }
    } else if (p.isSet(QStringLiteral("all"))) {
        for (const ParameterMeta& m : profile.parameters) {
            if (m.isReadable() && m.kind != QLatin1String("reserved"))
                names << m.name;
        }
    }
    for (const QString& n : names) {
        const ParameterMeta* m = profile.parameter(n);
        if (!m || !m->isReadable()) {
            context.err() << (m ? tr("error: %1 is a write-only command and cannot be read").arg(n)
                                : tr("error: %1 has no parameter \"%2\"; see \"opentop-cli params "
                                     "--family %1\"")
                                      .arg(profile.family, n))
                          << Qt::endl;
            return ExitUsage;
        }
    }
    DeviceSession::ReadManyOutcome result;
    if (!context.wait([&](std::function<void()> finish) {
            session->readMany(names, [&result, finish](const DeviceSession::ReadManyOutcome& o) {
                result = o;
                finish();
            });
        })) {
        context.err() << tr("interrupted") << Qt::endl;
        return ExitInterrupted;
    }
    const ValueContext valueContext = session->context();
    if (context.json()) {
        QJsonArray values;
        for (const QString& n : names) {
            const DeviceSession::Outcome o = result.results.value(n);
            const ParameterMeta& m = *profile.parameter(n);
            QJsonObject v{{QStringLiteral("name"), n}, {QStringLiteral("ok"), o.ok}};
            if (o.value.valid) {
                v.insert(QStringLiteral("registers"), registersJson(o.value.registers));
                v.insert(QStringLiteral("text"), ValueCodec::format(m, o.value, valueContext));
                v.insert(QStringLiteral("unit"), m.specFor(valueContext).unit);
                if (m.type == DataType::String)
                    v.insert(QStringLiteral("value"), o.value.text);
                else
                    v.insert(QStringLiteral("value"), o.value.number);
            }
            if (!o.error.isEmpty())
                v.insert(QStringLiteral("error"), o.error);
            values.append(v);
        }
        context.out() << QJsonDocument(QJsonObject{{QStringLiteral("slave"), slave},
                                                   {QStringLiteral("family"), profile.family},
                                                   {QStringLiteral("variant"), session->variant()},
                                                   {QStringLiteral("requests"), result.requests},
                                                   {QStringLiteral("values"), values}})
                             .toJson(QJsonDocument::Indented);
    } else {
        TextTable table({tr("Parameter"), tr("Value"), tr("Raw"), tr("Label")});
        for (const QString& n : names) {
            const DeviceSession::Outcome o = result.results.value(n);
            const ParameterMeta& m = *profile.parameter(n);
            QString value = o.value.valid ? ValueCodec::format(m, o.value, valueContext)
                                          : tr("(failed: %1)").arg(o.error);
            if (o.value.valid && !o.value.allowed)
                value += tr("  ! outside the profile's allowed values");
            table.addRow(
                {n, value, o.value.valid ? hexRegisters(o.value.registers) : QString(), m.label});
        }
        table.print(context.out());
    }
    if (result.failed > 0) {
        context.err() << QCoreApplication::translate("opentop::GetCommand",
                                                     "error: %n parameter(s) could not be read",
                                                     nullptr, result.failed)
                      << Qt::endl;
        return ExitCommunication;
    }
    return ExitOk;
}

int GetCommand::runRaw(CliContext& context, int slave)
{
    const QCommandLineParser& p = context.parser();
    const QStringList parts = p.value(QStringLiteral("raw")).split(QLatin1Char(':'));
    bool okAddress = false;
    bool okCount = parts.size() == 1;
    const QString a = parts.value(0).trimmed();
    const uint address = a.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                             ? a.mid(2).toUInt(&okAddress, 16)
                             : a.toUInt(&okAddress);
    const uint count = parts.size() == 2 ? parts[1].toUInt(&okCount) : 1;
    const int fc = p.isSet(QStringLiteral("fc")) ? p.value(QStringLiteral("fc")).toInt() : 3;
    if (!okAddress || !okCount || address > 0xFFFF || count < 1 || count > 125 ||
        (fc != 3 && fc != 4)) {
        context.err() << tr("error: --raw needs ADDR or ADDR:COUNT (address 0x0000–0xFFFF, count "
                            "1–125) and --fc 3 or 4")
                      << Qt::endl;
        return ExitUsage;
    }
    if (!context.connectBus())
        return ExitCommunication;
    const ModbusRequest request =
        fc == 4 ? ModbusRequest::readInput(quint8(slave), quint16(address), quint16(count))
                : ModbusRequest::readHolding(quint8(slave), quint16(address), quint16(count));
    ModbusResult result;
    if (!context.wait([&](std::function<void()> finish) {
            context.client()->submit(request, &context, [&result, finish](const ModbusResult& r) {
                result = r;
                finish();
            });
        }))
        return ExitInterrupted;
    if (!result.ok()) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(result.errorText()))
                      << Qt::endl;
        return ExitCommunication;
    }
    if (context.json()) {
        context.out() << QJsonDocument(QJsonObject{{QStringLiteral("slave"), slave},
                                                   {QStringLiteral("function"), fc},
                                                   {QStringLiteral("address"), int(address)},
                                                   {QStringLiteral("registers"),
                                                    registersJson(result.registers)}})
                             .toJson(QJsonDocument::Indented);
        return ExitOk;
    }
    TextTable table({tr("Address"), tr("Hex"), tr("Decimal")});
    table.setRightAligned(2);
    for (int i = 0; i < result.registers.size(); ++i) {
        const quint16 r = result.registers[i];
        table.addRow({QStringLiteral("0x%1")
                          .arg(address + uint(i), 4, 16, QLatin1Char('0'))
                          .toUpper()
                          .replace(QStringLiteral("0X"), QStringLiteral("0x")),
                      QStringLiteral("%1").arg(r, 4, 16, QLatin1Char('0')).toUpper(),
                      QString::number(r)});
    }
    table.print(context.out());
    return ExitOk;
}

} // namespace opentop
