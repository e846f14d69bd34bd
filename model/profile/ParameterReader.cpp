#include "model/profile/ParameterReader.h"

#include "model/profile/ValueCodec.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QSet>
#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ParameterReader", text);
}

const QStringList kKinds = {QStringLiteral("setting"), QStringLiteral("status"),
                            QStringLiteral("info"),    QStringLiteral("command"),
                            QStringLiteral("record"),  QStringLiteral("reserved")};
const QStringList kSafety = {QStringLiteral("motion"), QStringLiteral("reset"),
                             QStringLiteral("erase"),  QStringLiteral("init"),
                             QStringLiteral("store"),  QStringLiteral("comm")};
const QStringList kSpecKeys = {QStringLiteral("scale"),    QStringLiteral("unit"),
                               QStringLiteral("decimals"), QStringLiteral("allowed"),
                               QStringLiteral("enum"),     QStringLiteral("default"),
                               QStringLiteral("note"),     QStringLiteral("recommended")};

int decimalsForScale(double scale)
{
    int d = 0;
    while (d < 6 &&
           std::fabs(scale * std::pow(10.0, d) - std::round(scale * std::pow(10.0, d))) > 1e-9)
        ++d;
    return d;
}

} // namespace

bool ParameterReader::read(const QJsonObject& o, ParameterMeta* meta)
{
    static const QStringList known =
        QStringList{QStringLiteral("name"),       QStringLiteral("label"),
                    QStringLiteral("help"),       QStringLiteral("group"),
                    QStringLiteral("address"),    QStringLiteral("read"),
                    QStringLiteral("write"),      QStringLiteral("type"),
                    QStringLiteral("count"),      QStringLiteral("kind"),
                    QStringLiteral("when"),       QStringLiteral("bits"),
                    QStringLiteral("codeTable"),  QStringLiteral("safety"),
                    QStringLiteral("storeWith"),  QStringLiteral("backup"),
                    QStringLiteral("writeBlock"), QStringLiteral("wordOrder")} +
        kSpecKeys;
    if (!m_json.onlyKeys(o, known, tr("entry")))
        return false;
    const auto name = m_json.string(o, QStringLiteral("name"));
    if (!name)
        return false;
    meta->name = *name;
    static const QRegularExpression nameRe(QStringLiteral("^[a-z0-9_]+(\\.[a-z0-9_]+)*$"));
    if (!nameRe.match(meta->name).hasMatch())
        return m_json.fail(tr("name must be lower-case dotted words: [a-z0-9_] separated by dots"));
    meta->label = m_json.string(o, QStringLiteral("label")).value_or(QString());
    meta->canonicalLabel = meta->label;
    meta->help = m_json.string(o, QStringLiteral("help"), false).value_or(QString());
    meta->group = m_json.string(o, QStringLiteral("group")).value_or(QString());
    meta->kind = m_json.string(o, QStringLiteral("kind")).value_or(QString());
    if (m_json.failed())
        return false;
    if (meta->label.trimmed().isEmpty())
        return m_json.fail(tr("\"label\" is empty"));
    if (!m_profile.group(meta->group))
        return m_json.fail(tr("group \"%1\" is not declared in \"groups\"").arg(meta->group));
    if (!kKinds.contains(meta->kind))
        return m_json.fail(tr("kind must be one of %1").arg(kKinds.join(QStringLiteral(", "))));

    const auto address = m_json.integer(o, QStringLiteral("address"));
    if (!address)
        return false;
    if (*address < 0 || *address > 0xFFFF)
        return m_json.fail(tr("address must be 0x0000–0xFFFF"));
    meta->address = quint16(*address);
    const auto readFc = m_json.integer(o, QStringLiteral("read"), false);
    const auto writeFc = m_json.integer(o, QStringLiteral("write"), false);
    if (m_json.failed())
        return false;
    if (readFc && *readFc != 3 && *readFc != 4)
        return m_json.fail(tr("read must be 3 (holding) or 4 (input)"));
    if (writeFc && *writeFc != 6 && *writeFc != 16)
        return m_json.fail(tr("write must be 6 or 16"));
    meta->readFunction = readFc ? quint8(*readFc) : 0;
    meta->writeFunction = writeFc ? quint8(*writeFc) : 0;
    if (meta->readFunction == 4 && meta->writeFunction)
        return m_json.fail(tr("input registers (read 4) cannot be written"));
    if (meta->kind != QLatin1String("reserved") && !meta->readFunction && !meta->writeFunction)
        return m_json.fail(tr("neither readable nor writable"));
    meta->access = meta->readFunction && meta->writeFunction ? Access::ReadWrite
                   : meta->readFunction                      ? Access::ReadOnly
                                                             : Access::WriteOnly;

    const QString typeName = m_json.string(o, QStringLiteral("type")).value_or(QString());
    const std::optional<DataType> type = dataTypeFromName(typeName);
    if (!type)
        return m_json.fail(tr("type must be u16, s16, u32, s32, f32, string or bits"));
    meta->type = *type;
    const auto count = m_json.integer(o, QStringLiteral("count"), false);
    const int natural =
        (meta->type == DataType::U32 || meta->type == DataType::S32 || meta->type == DataType::F32)
            ? 2
            : 1;
    if (meta->type == DataType::String) {
        if (!count || *count < 1 || *count > 125)
            return m_json.fail(tr("string parameters need \"count\" 1–125 registers"));
        meta->registerCount = int(*count);
    } else if (meta->type == DataType::Bits) {
        meta->registerCount = count ? int(*count) : 1;
        if (meta->registerCount != 1 && meta->registerCount != 2)
            return m_json.fail(tr("bits parameters have \"count\" 1 or 2"));
    } else {
        meta->registerCount = natural;
        if (count && *count != natural)
            return m_json.fail(
                tr("%1 takes %2 register(s), not %3").arg(typeName).arg(natural).arg(*count));
    }
    if (const auto order = m_json.string(o, QStringLiteral("wordOrder"), false)) {
        const bool wide = meta->registerCount == 2 && meta->type != DataType::String;
        if (!wide)
            return m_json.fail(tr("\"wordOrder\" is for 2-register numbers and bit fields only"));
        if (*order == QLatin1String("low-first"))
            meta->wordOrder = WordOrder::LowFirst;
        else if (*order != QLatin1String("high-first"))
            return m_json.fail(tr("\"wordOrder\" must be \"high-first\" or \"low-first\""));
    }
    if (meta->registerCount > 1 && meta->writeFunction == 6)
        return m_json.fail(tr("a %1-register value cannot be written with function 06; use 16")
                               .arg(meta->registerCount));

    meta->safety = m_json.string(o, QStringLiteral("safety"), false).value_or(QString());
    if (!meta->safety.isEmpty() && !kSafety.contains(meta->safety))
        return m_json.fail(tr("safety must be one of %1").arg(kSafety.join(QStringLiteral(", "))));
    if (meta->kind == QLatin1String("command") && meta->writeFunction && meta->safety.isEmpty())
        return m_json.fail(tr("commands need a \"safety\" class"));
    meta->codeTable = m_json.string(o, QStringLiteral("codeTable"), false).value_or(QString());
    if (!meta->codeTable.isEmpty() && !m_profile.codeTable(meta->codeTable))
        return m_json.fail(tr("code table \"%1\" is not declared").arg(meta->codeTable));
    meta->storeWith = m_json.string(o, QStringLiteral("storeWith"), false).value_or(QString());
    if (const auto block = m_json.object(o, QStringLiteral("writeBlock"), false)) {
        if (!readWriteBlock(*block, meta))
            return false;
    }

    if (!readSpec(o, *meta, &meta->spec))
        return false;
    if (meta->kind == QLatin1String("setting") && meta->type != DataType::String &&
        meta->spec.ranges.isEmpty() && meta->spec.options.isEmpty())
        return m_json.fail(tr("a setting needs \"allowed\" or \"enum\""));
    if (meta->writeFunction && meta->type != DataType::String && meta->spec.ranges.isEmpty() &&
        meta->spec.options.isEmpty() && meta->kind != QLatin1String("reserved"))
        return m_json.fail(tr("a writable parameter needs \"allowed\" or \"enum\""));
    if (const auto bits = m_json.array(o, QStringLiteral("bits"), false)) {
        if (!readBits(*bits, meta))
            return false;
    } else if (meta->type == DataType::Bits) {
        return m_json.fail(tr("bits parameters need \"bits\""));
    }
    if (const auto when = m_json.array(o, QStringLiteral("when"), false)) {
        if (!readConditions(*when, meta))
            return false;
    }
    const QJsonValue backup = o.value(QStringLiteral("backup"));
    if (!backup.isUndefined() && !backup.isBool())
        return m_json.fail(tr("\"backup\" must be true or false"));
    meta->backup = backup.isBool() ? backup.toBool()
                                   : meta->kind == QLatin1String("setting") &&
                                         meta->access == Access::ReadWrite;
    if (meta->backup && meta->access != Access::ReadWrite)
        return m_json.fail(tr("only readable and writable parameters can be backed up"));
    return !m_json.failed();
}

bool ParameterReader::readWriteBlock(const QJsonObject& o, ParameterMeta* meta)
{
    const QString where = QStringLiteral("writeBlock");
    if (!m_json.onlyKeys(
            o, {QStringLiteral("address"), QStringLiteral("count"), QStringLiteral("tail")}, where))
        return false;
    const auto address = m_json.integer(o, QStringLiteral("address"));
    const auto count = m_json.integer(o, QStringLiteral("count"));
    if (!address || !count)
        return m_json.fail(tr("%1 needs \"address\" and \"count\"").arg(where));
    if (!meta->writeFunction)
        return m_json.fail(tr("%1: the parameter is not writable").arg(where));
    if (*address < 0 || *address > 0xFFFF || *count < 1 || *count > m_profile.maxWriteRegisters ||
        *address + *count > 0x10000)
        return m_json.fail(tr("%1: address 0x0000–0xFFFF and count 1–%2 (limits.maxWriteRegisters)")
                               .arg(where)
                               .arg(m_profile.maxWriteRegisters));
    meta->writeBlock.address = quint16(*address);
    meta->writeBlock.count = int(*count);
    if (const auto tail = m_json.array(o, QStringLiteral("tail"), false)) {
        for (const QJsonValue& v : *tail) {
            const double d = v.toDouble(-1);
            if (!v.isDouble() || d < 0 || d > 0xFFFF || d != std::floor(d))
                return m_json.fail(tr("%1: tail values are registers, 0–65535").arg(where));
            meta->writeBlock.tail << quint16(d);
        }
    }
    const int first = meta->writeBlock.address;
    const int readEnd = first + meta->writeBlock.readCount();
    if (meta->address < first || meta->address + meta->registerCount > readEnd)
        return m_json.fail(
            tr("%1: the parameter's registers must lie in the block, before its tail").arg(where));
    return !m_json.failed();
}

bool ParameterReader::readSpec(const QJsonObject& o, const ParameterMeta& meta, ValueSpec* spec)
{
    if (const auto scale = m_json.number(o, QStringLiteral("scale"), false)) {
        if (*scale <= 0)
            return m_json.fail(tr("scale must be positive"));
        spec->scale = *scale;
        spec->decimals = decimalsForScale(*scale);
    }
    if (meta.type == DataType::F32 && !o.contains(QStringLiteral("decimals")))
        spec->decimals = std::max(spec->decimals, 4);
    if (const auto unit = m_json.string(o, QStringLiteral("unit"), false)) {
        spec->unit = *unit;
        spec->canonicalUnit = *unit;
    }
    if (const auto decimals = m_json.integer(o, QStringLiteral("decimals"), false)) {
        if (*decimals < 0 || *decimals > 9)
            return m_json.fail(tr("decimals must be 0–9"));
        spec->decimals = int(*decimals);
    }
    if (const auto note = m_json.string(o, QStringLiteral("note"), false))
        spec->note = *note;
    if (const auto allowed = m_json.array(o, QStringLiteral("allowed"), false)) {
        spec->ranges.clear();
        if (!readRanges(*allowed, QStringLiteral("allowed"), meta, spec->scale, &spec->ranges))
            return false;
    }
    if (const auto recommended = m_json.array(o, QStringLiteral("recommended"), false)) {
        spec->recommended.clear();
        if (!readRanges(*recommended, QStringLiteral("recommended"), meta, spec->scale,
                        &spec->recommended))
            return false;
    }
    // A recommendation narrows what is allowed: each interval inside an allowed one.
    for (int i = 0; i < spec->recommended.size(); ++i) {
        const ValueRange& r = spec->recommended.at(i);
        const bool inside =
            std::any_of(spec->ranges.begin(), spec->ranges.end(),
                        [&r](const ValueRange& a) { return r.min >= a.min && r.max <= a.max; });
        if (!inside)
            return m_json.fail(
                tr("recommended[%1] is not inside one of the \"allowed\" intervals").arg(i));
    }
    if (const auto options = m_json.array(o, QStringLiteral("enum"), false)) {
        spec->options.clear();
        if (!readOptions(*options, meta, spec))
            return false;
    }
    if (m_json.failed())
        return false;
    const QJsonValue def = o.value(QStringLiteral("default"));
    if (def.isString() && meta.type == DataType::String) {
        spec->defaultText = def.toString();
    } else if (def.isDouble()) {
        // Enumeration defaults are codes; numeric defaults are engineering values.
        const bool isCode = spec->ranges.isEmpty() && !spec->options.isEmpty();
        const double raw = isCode ? def.toDouble() : def.toDouble() / spec->scale;
        const double rounded = meta.type == DataType::F32 ? raw : std::round(raw);
        if (std::fabs(raw - rounded) > 1e-6 * std::max(1.0, std::fabs(raw)))
            return m_json.fail(tr("default %1 is not a whole number of steps of %2")
                                   .arg(def.toDouble())
                                   .arg(spec->scale));
        spec->defaultRaw = rounded;
    } else if (def.isString()) {
        bool ok = false;
        const QString s = def.toString();
        const qint64 v = s.startsWith(QLatin1String("0x")) ? s.mid(2).toLongLong(&ok, 16) : 0;
        if (!ok)
            return m_json.fail(tr("default must be a number (or \"0x...\" code)"));
        spec->defaultRaw = double(v);
    } else if (!def.isUndefined() && !def.isNull()) {
        return m_json.fail(tr("default must be a number or a string"));
    }
    return true;
}

bool ParameterReader::readRanges(const QJsonArray& a, const QString& key, const ParameterMeta& meta,
                                 double scale, QVector<ValueRange>* ranges)
{
    for (int i = 0; i < a.size(); ++i) {
        const QString where = QStringLiteral("%1[%2]").arg(key).arg(i);
        if (!a[i].isObject())
            return m_json.fail(tr("%1 must be an object {\"min\":…, \"max\":…}").arg(where));
        const QJsonObject r = a[i].toObject();
        if (!m_json.onlyKeys(r, {QStringLiteral("min"), QStringLiteral("max")}, where))
            return false;
        const auto lo = m_json.number(r, QStringLiteral("min"));
        const auto hi = m_json.number(r, QStringLiteral("max"));
        if (!lo || !hi)
            return m_json.fail(tr("%1 needs numeric min and max").arg(where));
        ValueRange range{*lo / scale, *hi / scale};
        if (meta.type != DataType::F32) {
            for (double* v : {&range.min, &range.max}) {
                const double rounded = std::round(*v);
                if (std::fabs(*v - rounded) > 1e-6 * std::max(1.0, std::fabs(*v)))
                    return m_json.fail(tr("%1: %2 is not a whole number of steps of %3")
                                           .arg(where)
                                           .arg(*v * scale)
                                           .arg(scale));
                *v = rounded;
            }
        }
        if (range.min > range.max)
            return m_json.fail(tr("%1: min is greater than max").arg(where));
        *ranges << range;
    }
    return true;
}

bool ParameterReader::readOptions(const QJsonArray& a, const ParameterMeta& /*meta*/,
                                  ValueSpec* spec)
{
    QSet<qint64> codes;
    QSet<QString> labels;
    for (int i = 0; i < a.size(); ++i) {
        const QString where = QStringLiteral("enum[%1]").arg(i);
        if (!a[i].isObject())
            return m_json.fail(tr("%1 must be an object {\"value\":…, \"label\":…}").arg(where));
        const QJsonObject e = a[i].toObject();
        if (!m_json.onlyKeys(
                e, {QStringLiteral("value"), QStringLiteral("label"), QStringLiteral("help")},
                where))
            return false;
        EnumOption option;
        const auto value =
            m_json.integerValue(e.value(QStringLiteral("value")), where + QStringLiteral(".value"));
        if (!value)
            return false;
        option.value = *value;
        option.label = e.value(QStringLiteral("label")).toString();
        option.help = e.value(QStringLiteral("help")).toString();
        option.canonicalLabel = option.label;
        if (option.label.trimmed().isEmpty())
            return m_json.fail(tr("%1 has no label").arg(where));
        if (codes.contains(option.value) || labels.contains(option.label.toLower()))
            return m_json.fail(tr("%1 repeats a code or label").arg(where));
        codes.insert(option.value);
        labels.insert(option.label.toLower());
        spec->options << option;
    }
    return true;
}

bool ParameterReader::readBits(const QJsonArray& a, ParameterMeta* meta)
{
    if (meta->type != DataType::Bits)
        return m_json.fail(tr("\"bits\" only belongs to type bits"));
    const int width = meta->registerCount * 16;
    QSet<QString> names;
    for (int i = 0; i < a.size(); ++i) {
        const QString where = QStringLiteral("bits[%1]").arg(i);
        const QJsonObject b = a[i].toObject();
        if (!m_json.onlyKeys(b,
                             {QStringLiteral("bit"), QStringLiteral("width"),
                              QStringLiteral("name"), QStringLiteral("label"),
                              QStringLiteral("values"), QStringLiteral("function"),
                              QStringLiteral("appliesWhen")},
                             where))
            return false;
        BitField field;
        field.bit = int(m_json.integer(b, QStringLiteral("bit")).value_or(-1));
        field.width = int(m_json.integer(b, QStringLiteral("width"), false).value_or(1));
        field.name = m_json.string(b, QStringLiteral("name")).value_or(QString());
        field.label = m_json.string(b, QStringLiteral("label")).value_or(QString());
        field.function = m_json.string(b, QStringLiteral("function"), false).value_or(QString());
        if (b.contains(QStringLiteral("appliesWhen"))) {
            const QJsonObject when = b.value(QStringLiteral("appliesWhen")).toObject();
            field.appliesParam = when.value(QStringLiteral("param")).toString();
            field.appliesRaw = when.value(QStringLiteral("equals")).toDouble();
            if (field.appliesParam.isEmpty() || !when.value(QStringLiteral("equals")).isDouble())
                return m_json.fail(tr("%1.appliesWhen needs \"param\" and \"equals\"").arg(where));
        }
        if (m_json.failed())
            return false;
        if (field.bit < 0 || field.width < 1 || field.bit + field.width > width)
            return m_json.fail(tr("%1 lies outside the %2-bit register").arg(where).arg(width));
        if (field.name.isEmpty() || names.contains(field.name))
            return m_json.fail(tr("%1 needs a unique name").arg(where));
        names.insert(field.name);
        for (const QJsonValue& v : b.value(QStringLiteral("values")).toArray())
            field.values << v.toString();
        meta->bits << field;
    }
    return true;
}

bool ParameterReader::readConditions(const QJsonArray& a, ParameterMeta* meta)
{
    for (int i = 0; i < a.size(); ++i) {
        const QString where = QStringLiteral("when[%1]").arg(i);
        if (!a[i].isObject())
            return m_json.fail(tr("%1 must be an object").arg(where));
        const QJsonObject c = a[i].toObject();
        if (!m_json.onlyKeys(c,
                             QStringList{QStringLiteral("variant"), QStringLiteral("param"),
                                         QStringLiteral("equals")} +
                                 kSpecKeys,
                             where))
            return false;
        ValueCondition condition;
        condition.variant = c.value(QStringLiteral("variant")).toString();
        condition.param = c.value(QStringLiteral("param")).toString();
        if (condition.variant.isEmpty() == condition.param.isEmpty())
            return m_json.fail(tr("%1 needs either \"variant\" or \"param\"").arg(where));
        if (!condition.variant.isEmpty() && !m_profile.variant(condition.variant))
            return m_json.fail(
                tr("%1: variant \"%2\" is not declared").arg(where, condition.variant));
        if (!condition.param.isEmpty()) {
            const auto equals = m_json.integerValue(c.value(QStringLiteral("equals")),
                                                    where + QStringLiteral(".equals"));
            if (!equals)
                return false;
            condition.equals = *equals;
        }
        condition.spec = meta->spec;
        condition.spec.defaultRaw.reset();
        condition.ownUnit = c.contains(QStringLiteral("unit"));
        condition.ownNote = c.contains(QStringLiteral("note"));
        condition.ownOptions = c.contains(QStringLiteral("enum"));
        if (!readSpec(c, *meta, &condition.spec))
            return false;
        if (!condition.spec.defaultRaw)
            condition.spec.defaultRaw = meta->spec.defaultRaw;
        meta->conditions << condition;
    }
    return true;
}

} // namespace opentop
