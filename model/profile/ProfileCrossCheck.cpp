#include "model/profile/ProfileCrossCheck.h"

#include "model/profile/JsonReader.h"

#include <QCoreApplication>
#include <QHash>
#include <QRegularExpression>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ProfileCrossCheck", text);
}

} // namespace

bool ProfileCrossCheck::allows(const ValueSpec& spec, double raw)
{
    if (spec.ranges.isEmpty() && spec.options.isEmpty())
        return true;
    for (const EnumOption& o : spec.options) {
        if (double(o.value) == raw)
            return true;
    }
    for (const ValueRange& r : spec.ranges) {
        if (raw >= r.min && raw <= r.max)
            return true;
    }
    return false;
}

bool ProfileCrossCheck::check(const QJsonObject& root, JsonReader& json, Profile* profile)
{
    return checkParameters(json, profile) && readIdentify(root, json, profile);
}

bool ProfileCrossCheck::checkParameters(JsonReader& json, const Profile* p)
{
    QHash<quint32, QString> holding, input;
    for (const ParameterMeta& m : p->parameters) {
        const QString where = QStringLiteral("\"%1\"").arg(m.name);
        if (!m.storeWith.isEmpty()) {
            const ParameterMeta* store = p->parameter(m.storeWith);
            if (!store || store->kind != QLatin1String("command"))
                return json.fail(
                    tr("%1: storeWith \"%2\" is not a command parameter").arg(where, m.storeWith));
        }
        if (m.spec.defaultRaw && !allows(m.spec, *m.spec.defaultRaw))
            return json.fail(tr("%1: the default is not among its allowed values").arg(where));
        for (const BitField& b : m.bits) {
            const ParameterMeta* f = b.function.isEmpty() ? nullptr : p->parameter(b.function);
            if (!b.function.isEmpty() && (!f || !f->isReadable()))
                return json.fail(tr("%1: bit field \"%2\": function \"%3\" is not a readable "
                                    "parameter")
                                     .arg(where, b.name, b.function));
        }
        for (const ValueCondition& c : m.conditions) {
            if (!c.param.isEmpty() && (c.param == m.name || !p->parameter(c.param)))
                return json.fail(
                    tr("%1: condition on unknown parameter \"%2\"").arg(where, c.param));
            if (c.spec.defaultRaw && !allows(c.spec, *c.spec.defaultRaw))
                return json.fail(tr("%1: the default is not allowed when %2")
                                     .arg(where, c.variant.isEmpty() ? c.param : c.variant));
        }
        if (m.kind == QLatin1String("reserved") && !m.readFunction && !m.writeFunction)
            continue;
        const bool inInput = m.readFunction == 4;
        QHash<quint32, QString>& space = inInput ? input : holding;
        for (int r = 0; r < m.registerCount; ++r) {
            const quint32 address = quint32(m.address) + r;
            if (address > 0xFFFF)
                return json.fail(tr("%1 runs past address 0xFFFF").arg(where));
            if (space.contains(address))
                return json.fail(
                    tr("%1 overlaps \"%2\" at 0x%3 (%4 registers)")
                        .arg(where, space.value(address))
                        .arg(address, 4, 16, QLatin1Char('0'))
                        .arg(inInput ? QStringLiteral("input") : QStringLiteral("holding")));
            space.insert(address, m.name);
        }
    }
    return true;
}

bool ProfileCrossCheck::readIdentify(const QJsonObject& root, JsonReader& json, Profile* p)
{
    const QJsonObject id = json.object(root, QStringLiteral("identify")).value_or(QJsonObject());
    p->identify.function = quint8(json.integer(id, QStringLiteral("function")).value_or(0));
    p->identify.address = quint16(json.integer(id, QStringLiteral("address")).value_or(0));
    p->identify.count = quint16(json.integer(id, QStringLiteral("count")).value_or(0));
    p->identify.nameParameter = json.string(id, QStringLiteral("name")).value_or(QString());
    p->identify.versionParameter =
        json.string(id, QStringLiteral("version"), false).value_or(QString());
    p->identify.nameMatch = json.string(id, QStringLiteral("nameMatch"), false).value_or(QString());
    if (json.failed())
        return false;
    for (const QString& name : {p->identify.nameParameter, p->identify.versionParameter}) {
        if (name.isEmpty())
            continue;
        const ParameterMeta* m = p->parameter(name);
        if (!m || m->readFunction != p->identify.function || m->address < p->identify.address ||
            m->address + m->registerCount > p->identify.address + p->identify.count)
            return json.fail(
                tr("identify: \"%1\" must be a parameter inside the identify read").arg(name));
    }
    if (!QRegularExpression(p->identify.nameMatch).isValid())
        return json.fail(tr("identify.nameMatch is not a valid regular expression"));
    return true;
}

} // namespace opentop
