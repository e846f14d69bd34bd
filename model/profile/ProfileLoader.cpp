#include "model/profile/ProfileLoader.h"

#include "model/profile/JsonReader.h"
#include "model/profile/ParameterReader.h"
#include "model/profile/ProfileCrossCheck.h"
#include "model/profile/SettingReference.h"
#include "model/profile/VariantProbe.h"
#include "transport/LineFormat.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QSet>
#include <algorithm>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ProfileLoader", text);
}

bool readHeader(const QJsonObject& root, JsonReader& json, Profile* p)
{
    if (!json.onlyKeys(
            root,
            {QStringLiteral("schema"), QStringLiteral("family"), QStringLiteral("name"),
             QStringLiteral("vendor"), QStringLiteral("manual"), QStringLiteral("serial"),
             QStringLiteral("limits"), QStringLiteral("variants"), QStringLiteral("identify"),
             QStringLiteral("readBlocks"), QStringLiteral("groups"), QStringLiteral("codeTables"),
             QStringLiteral("parameters"), QStringLiteral("roles"), QStringLiteral("tuning"),
             QStringLiteral("decelerationKnobs"), QStringLiteral("statusLed"),
             QStringLiteral("address"), QStringLiteral("variantProbe")},
            tr("top level")))
        return false;
    if (json.integer(root, QStringLiteral("schema")).value_or(0) != 1)
        return json.fail(tr("\"schema\" must be 1"));
    p->family = json.string(root, QStringLiteral("family")).value_or(QString());
    p->name = json.string(root, QStringLiteral("name")).value_or(QString());
    p->vendor = json.string(root, QStringLiteral("vendor"), false).value_or(QString());
    p->manual = json.string(root, QStringLiteral("manual"), false).value_or(QString());
    p->tuning = root.value(QStringLiteral("tuning")).toObject(); // checked by TuningSpec
    p->variantProbe = root.value(QStringLiteral("variantProbe")).toObject();
    if (json.failed())
        return false;
    static const QRegularExpression idRe(QStringLiteral("^[a-z][a-z0-9_]*$"));
    if (!idRe.match(p->family).hasMatch())
        return json.fail(tr("\"family\" must be a lower-case id"));
    const QJsonObject serial = json.object(root, QStringLiteral("serial")).value_or(QJsonObject());
    p->serial.baud = int(json.integer(serial, QStringLiteral("baud")).value_or(0));
    const QString parity = json.string(serial, QStringLiteral("parity")).value_or(QString());
    p->serial.stopBits = int(json.integer(serial, QStringLiteral("stopBits")).value_or(0));
    if (json.failed())
        return false;
    if (parity.size() != 1 || !QStringLiteral("NEO").contains(parity))
        return json.fail(tr("serial.parity must be N, E or O"));
    p->serial.parity = parity.at(0).toLatin1();
    if (p->serial.baud < 1200 || p->serial.baud > 115200 ||
        (p->serial.stopBits != 1 && p->serial.stopBits != 2))
        return json.fail(tr("serial: baud must be 1200–115200 and stopBits 1 or 2"));
    for (const QJsonValue& b : serial.value(QStringLiteral("bauds")).toArray())
        p->serial.bauds << b.toInt();
    p->serial.powerOnDelayMs =
        int(json.integer(serial, QStringLiteral("powerOnDelayMs"), false).value_or(0));
    const QString defaultFrame =
        LineFormat{p->serial.baud, p->serial.parity, 8, p->serial.stopBits}.frameText();
    const QJsonArray formats = serial.value(QStringLiteral("formats")).toArray();
    for (const QJsonValue& f : formats.isEmpty() ? QJsonArray{defaultFrame} : formats) {
        const std::optional<LineFormat> format = LineFormat::parse(f.toString(), p->serial.baud);
        if (!format || format->baud != p->serial.baud)
            return json.fail(
                tr("serial.formats: \"%1\" is not a format such as 8N1 or 8E1").arg(f.toString()));
        p->serial.formats << format->frameText();
    }
    if (!p->serial.formats.contains(defaultFrame))
        return json.fail(tr("serial.formats must hold the default format %1").arg(defaultFrame));
    p->serial.formatHelp =
        json.string(serial, QStringLiteral("formatHelp"), false).value_or(QString());
    if (p->serial.powerOnDelayMs < 0 || p->serial.powerOnDelayMs > 60000)
        return json.fail(tr("serial.powerOnDelayMs must be 0–60000"));
    const QJsonObject limits = json.object(root, QStringLiteral("limits")).value_or(QJsonObject());
    p->maxReadRegisters = int(json.integer(limits, QStringLiteral("maxReadRegisters")).value_or(0));
    p->maxWriteRegisters =
        int(json.integer(limits, QStringLiteral("maxWriteRegisters")).value_or(0));
    p->minSlave = int(json.integer(limits, QStringLiteral("minSlave")).value_or(0));
    p->maxSlave = int(json.integer(limits, QStringLiteral("maxSlave")).value_or(0));
    p->supportsBroadcast = limits.value(QStringLiteral("broadcast")).toBool(false);
    p->supportsGroups = limits.value(QStringLiteral("groups")).toBool(false);
    if (json.failed())
        return false;
    if (p->maxReadRegisters < 1 || p->maxReadRegisters > 125 || p->maxWriteRegisters < 1 ||
        p->maxWriteRegisters > 123)
        return json.fail(tr("limits: maxReadRegisters 1–125, maxWriteRegisters 1–123"));
    if (p->minSlave < 1 || p->maxSlave > 247 || p->minSlave > p->maxSlave)
        return json.fail(tr("limits: slaves must lie in 1–247"));
    return AddressSwitches::read(root, json, p->maxSlave, &p->addressSwitches);
}

bool readVariantsGroupsBlocks(const QJsonObject& root, JsonReader& json, Profile* p)
{
    const QJsonArray variants = root.value(QStringLiteral("variants")).toArray();
    for (int i = 0; i < variants.size(); ++i) {
        const QJsonObject v = variants[i].toObject();
        ProfileVariant variant;
        variant.id = json.string(v, QStringLiteral("id")).value_or(QString());
        variant.model = json.string(v, QStringLiteral("model")).value_or(QString());
        variant.label = json.string(v, QStringLiteral("label")).value_or(QString());
        variant.nameMatch = json.string(v, QStringLiteral("nameMatch"), false).value_or(QString());
        if (json.failed())
            return json.fail(tr("variants[%1] needs id, model and label").arg(i));
        if (p->variant(variant.id))
            return json.fail(tr("variants[%1]: id \"%2\" repeated").arg(i).arg(variant.id));
        p->variants << variant;
    }
    const QJsonArray groups = json.array(root, QStringLiteral("groups")).value_or(QJsonArray());
    for (int i = 0; i < groups.size(); ++i) {
        const QJsonObject g = groups[i].toObject();
        ProfileGroup group{json.string(g, QStringLiteral("id")).value_or(QString()),
                           json.string(g, QStringLiteral("label")).value_or(QString()),
                           json.string(g, QStringLiteral("help"), false).value_or(QString()),
                           json.string(g, QStringLiteral("editor"), false).value_or(QString())};
        if (json.failed() || p->group(group.id))
            return json.fail(tr("groups[%1] needs a unique id and a label").arg(i));
        p->groups << group;
    }
    const QJsonArray blocks = root.value(QStringLiteral("readBlocks")).toArray();
    for (int i = 0; i < blocks.size(); ++i) {
        const QJsonObject b = blocks[i].toObject();
        const auto fc = json.integer(b, QStringLiteral("function"));
        const auto first = json.integer(b, QStringLiteral("first"));
        const auto last = json.integer(b, QStringLiteral("last"));
        if (json.failed() || (*fc != 3 && *fc != 4) || *first < 0 || *last > 0xFFFF ||
            *first > *last)
            return json.fail(tr("readBlocks[%1] needs function 3 or 4 and first ≤ last").arg(i));
        p->readBlocks << ReadBlock{quint8(*fc), quint16(*first), quint16(*last)};
    }
    return true;
}

bool readCodeTables(const QJsonObject& root, JsonReader& json, Profile* p)
{
    static const QStringList resets = {QStringLiteral("alarm-reset"), QStringLiteral("power"),
                                       QStringLiteral("auto"), QStringLiteral("none")};
    const QJsonObject tables = root.value(QStringLiteral("codeTables")).toObject();
    for (auto it = tables.begin(); it != tables.end(); ++it) {
        CodeTable table;
        table.id = it.key();
        const QJsonObject t = it.value().toObject();
        table.label = t.value(QStringLiteral("label")).toString();
        const QJsonArray entries = t.value(QStringLiteral("entries")).toArray();
        for (int i = 0; i < entries.size(); ++i) {
            const QJsonObject e = entries[i].toObject();
            const QString where = QStringLiteral("codeTables.%1.entries[%2]").arg(table.id).arg(i);
            if (!json.onlyKeys(e,
                               {QStringLiteral("code"), QStringLiteral("panel"),
                                QStringLiteral("name"), QStringLiteral("reset"),
                                QStringLiteral("resetText"), QStringLiteral("cause"),
                                QStringLiteral("remedy"), QStringLiteral("led"),
                                QStringLiteral("exception"), QStringLiteral("retry")},
                               where))
                return false;
            CodeEntry entry;
            const auto code =
                json.integerValue(e.value(QStringLiteral("code")), where + QStringLiteral(".code"));
            if (!code)
                return false;
            entry.code = *code;
            entry.panel = e.value(QStringLiteral("panel")).toString();
            entry.name = e.value(QStringLiteral("name")).toString();
            entry.reset = e.value(QStringLiteral("reset")).toString();
            entry.resetText = e.value(QStringLiteral("resetText")).toString();
            entry.cause = e.value(QStringLiteral("cause")).toString();
            entry.remedy = e.value(QStringLiteral("remedy")).toString();
            entry.led = e.value(QStringLiteral("led")).toString();
            entry.exceptionCode = e.value(QStringLiteral("exception")).toInt();
            entry.retry = e.value(QStringLiteral("retry")).toBool();
            if (entry.name.isEmpty())
                return json.fail(tr("%1 has no name").arg(where));
            if (!entry.reset.isEmpty() && !resets.contains(entry.reset))
                return json.fail(tr("%1: reset must be one of %2")
                                     .arg(where, resets.join(QStringLiteral(", "))));
            if (table.find(entry.code))
                return json.fail(tr("%1: code %2 repeated").arg(where).arg(entry.code));
            table.entries << entry;
        }
        p->codeTables.insert(table.id, table);
    }
    return true;
}

bool readRoles(const QJsonObject& root, JsonReader& json, Profile* p)
{
    const QJsonObject roles = root.value(QStringLiteral("roles")).toObject();
    for (auto it = roles.begin(); it != roles.end(); ++it) {
        const QString where = QStringLiteral("roles.%1").arg(it.key());
        ProfileRole role;
        auto known = [&](const QString& name) {
            if (!p->parameter(name))
                return json.fail(tr("%1: unknown parameter \"%2\"").arg(where, name));
            return true;
        };
        if (it.value().isString()) {
            role.parameter = it.value().toString();
        } else if (it.value().isArray()) {
            for (const QJsonValue& v : it.value().toArray()) {
                if (!known(v.toString()))
                    return false;
                role.parameters << v.toString();
            }
        } else if (it.value().isObject()) {
            const QJsonObject o = it.value().toObject();
            if (!json.onlyKeys(
                    o, {QStringLiteral("param"), QStringLiteral("field"), QStringLiteral("value")},
                    where))
                return false;
            role.parameter = o.value(QStringLiteral("param")).toString();
            role.field = o.value(QStringLiteral("field")).toString();
            if (o.contains(QStringLiteral("value"))) {
                const auto v = json.integerValue(o.value(QStringLiteral("value")),
                                                 where + QStringLiteral(".value"));
                if (!v)
                    return false;
                role.value = *v;
            }
        } else {
            return json.fail(
                tr("%1 must be a parameter name, a list of names or an object").arg(where));
        }
        if (role.parameters.isEmpty() && !known(role.parameter))
            return false;
        if (!role.field.isEmpty()) {
            const ParameterMeta* m = p->parameter(role.parameter);
            const bool found = std::any_of(m->bits.begin(), m->bits.end(),
                                           [&](const BitField& b) { return b.name == role.field; });
            if (!found)
                return json.fail(tr("%1: \"%2\" has no bit field \"%3\"")
                                     .arg(where, role.parameter, role.field));
        }
        if (role.value) {
            const ParameterMeta* m = p->parameter(role.parameter);
            if (!m->isWritable() || !ProfileCrossCheck::allows(m->spec, double(*role.value)))
                return json.fail(tr("%1: %2 is not a value \"%3\" can be written with")
                                     .arg(where)
                                     .arg(*role.value)
                                     .arg(role.parameter));
        }
        p->roles.insert(it.key(), role);
    }
    return true;
}

bool readDecelerationKnobs(const QJsonObject& root, JsonReader& json, Profile* p)
{
    const QJsonArray knobs = root.value(QStringLiteral("decelerationKnobs")).toArray();
    if (knobs.isEmpty())
        return true;
    const ProfileRole* selected = p->role(QStringLiteral("selected"));
    const ParameterMeta* meta = selected ? p->parameter(selected->parameter) : nullptr;
    if (!meta)
        return json.fail(tr("decelerationKnobs need the \"selected\" role"));
    int width = 16;
    for (const BitField& b : meta->bits) {
        if (b.name == selected->field)
            width = b.width;
    }
    for (int i = 0; i < knobs.size(); ++i) {
        const QString where = QStringLiteral("decelerationKnobs[%1]").arg(i);
        const QJsonObject o = knobs[i].toObject();
        if (!json.onlyKeys(o, {QStringLiteral("selected"), QStringLiteral("maxSeconds")}, where))
            return false;
        DecelerationKnob k;
        const auto value = json.integerValue(o.value(QStringLiteral("selected")),
                                             where + QStringLiteral(".selected"));
        const auto seconds = json.number(o, QStringLiteral("maxSeconds"));
        if (!value || !seconds)
            return json.fail(tr("%1 needs \"selected\" and \"maxSeconds\"").arg(where));
        if (*value < 0 || *value >= (qint64(1) << width) || p->knobDeceleration(*value))
            return json.fail(
                tr("%1: \"selected\" %2 is not a value of the \"selected\" role, or repeated")
                    .arg(where)
                    .arg(*value));
        if (*seconds <= 0 || *seconds > 600)
            return json.fail(
                tr("%1: \"maxSeconds\" must be more than 0 and at most 600").arg(where));
        k.selected = *value;
        k.maxSeconds = *seconds;
        p->decelerationKnobs << k;
    }
    return true;
}

bool readStatusLed(const QJsonObject& root, JsonReader& json, Profile* p)
{
    static const QStringList lights = {QStringLiteral("green"),   QStringLiteral("orange"),
                                       QStringLiteral("skyBlue"), QStringLiteral("red"),
                                       QStringLiteral("purple"),  QStringLiteral("blue"),
                                       QStringLiteral("white")};
    static const QRegularExpression colourRe(QStringLiteral("^#[0-9a-fA-F]{6}$"));
    const QJsonArray entries = root.value(QStringLiteral("statusLed")).toArray();
    for (int i = 0; i < entries.size(); ++i) {
        const QString where = QStringLiteral("statusLed[%1]").arg(i);
        const QJsonObject o = entries[i].toObject();
        if (!json.onlyKeys(o,
                           {QStringLiteral("light"), QStringLiteral("colour"),
                            QStringLiteral("label"), QStringLiteral("meaning"),
                            QStringLiteral("blink")},
                           where))
            return false;
        StatusLedEntry e;
        e.light = o.value(QStringLiteral("light")).toString();
        e.colour = o.value(QStringLiteral("colour")).toString();
        e.label = o.value(QStringLiteral("label")).toString();
        e.meaning = o.value(QStringLiteral("meaning")).toString();
        e.blink = o.value(QStringLiteral("blink")).toString();
        if (!lights.contains(e.light) || p->ledEntry(e.light))
            return json.fail(tr("%1: \"light\" must be one of %2, each once")
                                 .arg(where, lights.join(QStringLiteral(", "))));
        if (!colourRe.match(e.colour).hasMatch())
            return json.fail(tr("%1: \"colour\" must be #rrggbb").arg(where));
        if (e.label.trimmed().isEmpty() || e.meaning.trimmed().isEmpty())
            return json.fail(tr("%1: \"label\" and \"meaning\" must not be empty").arg(where));
        p->statusLed << e;
    }
    return true;
}

} // namespace

std::optional<Profile> ProfileLoader::loadJson(const QByteArray& data, const QString& sourceName,
                                               QString* error)
{
    QString detail;
    auto failWith = [&](const QString& message) {
        if (error)
            *error = sourceName + QStringLiteral(": ") + message;
        return std::nullopt;
    };
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(data, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return failWith(tr("not valid JSON at offset %1: %2")
                            .arg(parseError.offset)
                            .arg(parseError.errorString()));
    if (!doc.isObject())
        return failWith(tr("the top level must be a JSON object"));
    const QJsonObject root = doc.object();
    JsonReader json(&detail);
    Profile profile;
    profile.sourceFile = sourceName;
    if (!readHeader(root, json, &profile) || !readVariantsGroupsBlocks(root, json, &profile) ||
        !readCodeTables(root, json, &profile))
        return failWith(detail);

    const QJsonArray params = json.array(root, QStringLiteral("parameters")).value_or(QJsonArray());
    if (json.failed() || params.isEmpty())
        return failWith(json.failed() ? detail : tr("\"parameters\" is empty"));
    QSet<QString> names;
    for (int i = 0; i < params.size(); ++i) {
        const QJsonObject o = params[i].toObject();
        ParameterMeta meta;
        ParameterReader reader(profile, json);
        const QString label = QStringLiteral("parameters[%1] \"%2\"")
                                  .arg(i)
                                  .arg(o.value(QStringLiteral("name")).toString());
        if (!params[i].isObject() || !reader.read(o, &meta))
            return failWith(label + QStringLiteral(": ") +
                            (detail.isEmpty() ? tr("must be an object") : detail));
        if (names.contains(meta.name))
            return failWith(label + QStringLiteral(": ") + tr("name repeated"));
        names.insert(meta.name);
        profile.parameters << meta;
    }
    profile.index();
    if (!ProfileCrossCheck::check(root, json, &profile) || !readRoles(root, json, &profile) ||
        !readDecelerationKnobs(root, json, &profile) || !readStatusLed(root, json, &profile))
        return failWith(detail);
    if (const QString probe = VariantProbe::check(profile, profile.variantProbe); !probe.isEmpty())
        return failWith(probe);
    if (const QString unknown = SettingReference::firstUnknown(profile); !unknown.isEmpty())
        return failWith(tr("texts: {setting:…} names no parameter (%1)").arg(unknown));
    return profile;
}

std::optional<Profile> ProfileLoader::loadFile(const QString& path, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("%1: cannot open: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    return loadJson(file.readAll(), QFileInfo(path).fileName(), error);
}

} // namespace opentop
