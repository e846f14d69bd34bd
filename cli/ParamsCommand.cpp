#include "cli/ParamsCommand.h"

#include "cli/CliContext.h"
#include "cli/TextTable.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ParamsCommand", text);
}

QJsonObject specJson(const ValueSpec& spec)
{
    QJsonObject o;
    o.insert(QStringLiteral("scale"), spec.scale);
    o.insert(QStringLiteral("unit"), spec.unit);
    o.insert(QStringLiteral("decimals"), spec.decimals);
    QJsonArray ranges;
    for (const ValueRange& r : spec.ranges)
        ranges.append(QJsonObject{{QStringLiteral("min"), r.min * spec.scale},
                                  {QStringLiteral("max"), r.max * spec.scale}});
    o.insert(QStringLiteral("allowed"), ranges);
    QJsonArray options;
    for (const EnumOption& e : spec.options)
        options.append(QJsonObject{{QStringLiteral("value"), double(e.value)},
                                   {QStringLiteral("label"), e.label}});
    o.insert(QStringLiteral("enum"), options);
    if (spec.defaultRaw) {
        const bool code = spec.ranges.isEmpty() && !spec.options.isEmpty();
        o.insert(QStringLiteral("default"),
                 code ? *spec.defaultRaw : *spec.defaultRaw * spec.scale);
    }
    if (!spec.note.isEmpty())
        o.insert(QStringLiteral("note"), spec.note);
    return o;
}

QString defaultText(const ParameterMeta& meta)
{
    if (!meta.spec.defaultRaw)
        return meta.spec.defaultText.isEmpty() ? QStringLiteral("—") : meta.spec.defaultText;
    ParamValue v =
        ValueCodec::decode(meta, ValueCodec::rawToRegisters(meta, *meta.spec.defaultRaw));
    return ValueCodec::format(meta, v);
}

// Allowed values for every case a parameter can be in, e.g. the I/O function codes of Mode1
// and of Mode2, and the DBU400's narrower speed range.
QString allowedSummary(const ParameterMeta& meta)
{
    QStringList parts;
    if (!meta.dependsOnParameter())
        parts << ValueCodec::allowedText(meta);
    for (const ValueCondition& c : meta.conditions) {
        ValueContext context;
        context.variant = c.variant;
        if (!c.param.isEmpty()) {
            context.parameterRaw = [&c](const QString& name) -> std::optional<qint64> {
                return name == c.param ? std::optional<qint64>(c.equals) : std::nullopt;
            };
        }
        const QString when =
            c.variant.isEmpty() ? QStringLiteral("%1=%2").arg(c.param).arg(c.equals) : c.variant;
        parts << when + QStringLiteral(": ") + ValueCodec::allowedText(meta, context);
    }
    return parts.join(QStringLiteral("; "));
}

} // namespace

QString ParamsCommand::summary() const
{
    return tr("List every parameter of the device profiles");
}

QJsonObject ParamsCommand::toJson(const ParameterMeta& meta)
{
    QJsonObject o = specJson(meta.spec);
    o.insert(QStringLiteral("name"), meta.name);
    o.insert(QStringLiteral("label"), meta.label);
    o.insert(QStringLiteral("help"), meta.help);
    o.insert(QStringLiteral("group"), meta.group);
    o.insert(QStringLiteral("address"), int(meta.address));
    o.insert(QStringLiteral("addressHex"), meta.addressText());
    o.insert(QStringLiteral("readFunction"),
             meta.readFunction ? QJsonValue(int(meta.readFunction)) : QJsonValue());
    o.insert(QStringLiteral("writeFunction"),
             meta.writeFunction ? QJsonValue(int(meta.writeFunction)) : QJsonValue());
    o.insert(QStringLiteral("type"), dataTypeName(meta.type));
    o.insert(QStringLiteral("registers"), meta.registerCount);
    o.insert(QStringLiteral("access"), accessName(meta.access));
    o.insert(QStringLiteral("kind"), meta.kind);
    o.insert(QStringLiteral("allowedText"), allowedSummary(meta));
    o.insert(QStringLiteral("backup"), meta.backup);
    if (!meta.safety.isEmpty())
        o.insert(QStringLiteral("safety"), meta.safety);
    if (!meta.storeWith.isEmpty())
        o.insert(QStringLiteral("storeWith"), meta.storeWith);
    if (!meta.codeTable.isEmpty())
        o.insert(QStringLiteral("codeTable"), meta.codeTable);
    QJsonArray bits;
    for (const BitField& b : meta.bits) {
        bits.append(QJsonObject{{QStringLiteral("bit"), b.bit},
                                {QStringLiteral("width"), b.width},
                                {QStringLiteral("name"), b.name},
                                {QStringLiteral("label"), b.label},
                                {QStringLiteral("values"), QJsonArray::fromStringList(b.values)}});
    }
    if (!bits.isEmpty())
        o.insert(QStringLiteral("bits"), bits);
    QJsonArray conditions;
    for (const ValueCondition& c : meta.conditions) {
        QJsonObject j = specJson(c.spec);
        if (!c.variant.isEmpty())
            j.insert(QStringLiteral("variant"), c.variant);
        else {
            j.insert(QStringLiteral("param"), c.param);
            j.insert(QStringLiteral("equals"), double(c.equals));
        }
        conditions.append(j);
    }
    if (!conditions.isEmpty())
        o.insert(QStringLiteral("when"), conditions);
    return o;
}

QJsonObject ParamsCommand::toJson(const Profile& profile)
{
    QJsonArray variants;
    for (const ProfileVariant& v : profile.variants)
        variants.append(QJsonObject{{QStringLiteral("id"), v.id},
                                    {QStringLiteral("model"), v.model},
                                    {QStringLiteral("label"), v.label}});
    QJsonArray groups;
    for (const ProfileGroup& g : profile.groups)
        groups.append(
            QJsonObject{{QStringLiteral("id"), g.id}, {QStringLiteral("label"), g.label}});
    QJsonArray params;
    for (const ParameterMeta& m : profile.parameters) {
        if (m.kind != QLatin1String("reserved"))
            params.append(toJson(m));
    }
    return QJsonObject{{QStringLiteral("family"), profile.family},
                       {QStringLiteral("name"), profile.name},
                       {QStringLiteral("variants"), variants},
                       {QStringLiteral("groups"), groups},
                       {QStringLiteral("parameters"), params}};
}

int ParamsCommand::run(CliContext& context, const QStringList& args)
{
    if (!args.isEmpty()) {
        context.err() << tr("error: params takes no arguments; use --family F") << Qt::endl;
        return ExitUsage;
    }
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    QVector<const Profile*> profiles;
    if (context.parser().isSet(QStringLiteral("family"))) {
        const Profile* p = registry.family(context.parser().value(QStringLiteral("family")));
        if (!p) {
            context.err() << tr("error: unknown family \"%1\"; known: %2")
                                 .arg(context.parser().value(QStringLiteral("family")),
                                      registry.families().join(QStringLiteral(", ")))
                          << Qt::endl;
            return ExitUsage;
        }
        profiles << p;
    } else {
        for (const Profile& p : registry.profiles())
            profiles << &p;
    }
    if (context.json()) {
        QJsonArray families;
        for (const Profile* p : profiles)
            families.append(toJson(*p));
        context.out() << QJsonDocument(QJsonObject{{QStringLiteral("schema"), 1},
                                                   {QStringLiteral("families"), families}})
                             .toJson(QJsonDocument::Indented);
        return ExitOk;
    }
    for (const Profile* p : profiles) {
        context.out() << p->name << " (" << p->family << ")\n";
        TextTable table({tr("Name"), tr("Label"), tr("Address"), tr("FC"), tr("Type"), tr("Unit"),
                         tr("Allowed"), tr("Default"), tr("Access"), tr("Group")});
        for (const ParameterMeta& m : p->parameters) {
            if (m.kind == QLatin1String("reserved"))
                continue;
            table.addRow({m.name, m.label, m.addressText(), m.functionsText(), dataTypeName(m.type),
                          m.spec.unit, allowedSummary(m), defaultText(m), accessName(m.access),
                          m.group});
        }
        table.print(context.out());
        context.out() << '\n';
    }
    return ExitOk;
}

} // namespace opentop
