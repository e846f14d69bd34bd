#include "model/eol/UnitRecordJson.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace opentop {

namespace {

QJsonValue optionalNumber(const std::optional<double>& value)
{
    return value ? QJsonValue(*value) : QJsonValue(QJsonValue::Undefined);
}

std::optional<double> numberOrNothing(const QJsonValue& value)
{
    if (value.isDouble())
        return value.toDouble();
    return std::nullopt;
}

} // namespace

QString UnitRecordJson::timeText(const QDateTime& time)
{
    if (!time.isValid())
        return QString();
    return time.toUTC().toString(Qt::ISODateWithMs);
}

QDateTime UnitRecordJson::timeFromText(const QString& text)
{
    if (text.isEmpty())
        return QDateTime();
    QDateTime time = QDateTime::fromString(text, Qt::ISODateWithMs);
    return time.isValid() ? time.toUTC() : QDateTime();
}

QJsonObject UnitRecordJson::toJson(const UnitRecord& r)
{
    QJsonArray drives;
    for (const UnitDrive& d : r.drives) {
        QJsonObject o{{QStringLiteral("machineNumber"), d.machineNumber},
                      {QStringLiteral("model"), d.model},
                      {QStringLiteral("variant"), d.variant},
                      {QStringLiteral("firmware"), d.firmware}};
        // How the variant was known: "read", "probed", "confirmed" or "assumed".
        if (d.variantSource != VariantSource::None)
            o.insert(QStringLiteral("variantSource"), variantSourceName(d.variantSource));
        if (!d.variantProof.isEmpty())
            o.insert(QStringLiteral("variantProof"), d.variantProof);
        drives.append(o);
    }
    QJsonArray written;
    for (const WrittenValue& w : r.writtenValues)
        written.append(QJsonObject{{QStringLiteral("machineNumber"), w.machineNumber},
                                   {QStringLiteral("parameter"), w.parameter},
                                   {QStringLiteral("label"), w.label},
                                   {QStringLiteral("value"), w.value},
                                   {QStringLiteral("written"), w.written},
                                   {QStringLiteral("verified"), w.verified},
                                   {QStringLiteral("readBack"), w.readBack}});
    QJsonArray measured;
    for (const Measurement& m : r.measurements) {
        QJsonObject o{
            {QStringLiteral("machineNumber"), m.machineNumber},
            {QStringLiteral("step"), m.step},
            {QStringLiteral("quantity"), m.quantity},
            {QStringLiteral("value"), m.value},
            {QStringLiteral("unit"), m.unit},
            {QStringLiteral("verdict"), m.pass ? QStringLiteral("pass") : QStringLiteral("fail")}};
        if (m.lower)
            o.insert(QStringLiteral("lower"), optionalNumber(m.lower));
        if (m.upper)
            o.insert(QStringLiteral("upper"), optionalNumber(m.upper));
        measured.append(o);
    }
    return QJsonObject{
        {QStringLiteral("format"), formatName()},
        {QStringLiteral("version"), kFormatVersion},
        {QStringLiteral("id"), r.id},
        {QStringLiteral("serial"), r.serial},
        {QStringLiteral("station"), r.station},
        {QStringLiteral("operator"), r.operatorName},
        {QStringLiteral("started"), timeText(r.started)},
        {QStringLiteral("ended"), timeText(r.ended)},
        {QStringLiteral("recipe"), QJsonObject{{QStringLiteral("name"), r.recipeName},
                                               {QStringLiteral("revision"), r.recipeRevision},
                                               {QStringLiteral("checksum"), r.recipeChecksum},
                                               {QStringLiteral("approval"), r.approvalId},
                                               {QStringLiteral("approver"), r.approver}}},
        {QStringLiteral("status"), unitStatusName(r.status)},
        {QStringLiteral("attempt"), r.attempt},
        {QStringLiteral("failureReason"), r.failureReason},
        {QStringLiteral("drives"), drives},
        {QStringLiteral("writtenValues"), written},
        {QStringLiteral("measurements"), measured},
        {QStringLiteral("traffic"), QJsonArray::fromStringList(r.traffic)},
    };
}

QByteArray UnitRecordJson::toBytes(const UnitRecord& record)
{
    return QJsonDocument(toJson(record)).toJson(QJsonDocument::Indented);
}

std::optional<UnitRecord> UnitRecordJson::fromJson(const QJsonObject& json, QString* error)
{
    auto fail = [&](const QString& why) -> std::optional<UnitRecord> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (json.value(QStringLiteral("format")).toString() != formatName())
        return fail(tr("not a unit record (format is not \"%1\")").arg(formatName()));
    const int version = json.value(QStringLiteral("version")).toInt();
    if (version < 1 || version > kFormatVersion)
        return fail(tr("unit record version %1 is not known to this program (it reads up to %2)")
                        .arg(version)
                        .arg(kFormatVersion));
    UnitRecord r;
    r.id = json.value(QStringLiteral("id")).toString();
    r.serial = json.value(QStringLiteral("serial")).toString();
    if (r.serial.isEmpty())
        return fail(tr("the unit record has no serial number"));
    r.station = json.value(QStringLiteral("station")).toString();
    r.operatorName = json.value(QStringLiteral("operator")).toString();
    r.started = timeFromText(json.value(QStringLiteral("started")).toString());
    r.ended = timeFromText(json.value(QStringLiteral("ended")).toString());
    const QJsonObject recipe = json.value(QStringLiteral("recipe")).toObject();
    r.recipeName = recipe.value(QStringLiteral("name")).toString();
    r.recipeRevision = recipe.value(QStringLiteral("revision")).toString();
    r.recipeChecksum = recipe.value(QStringLiteral("checksum")).toString();
    r.approvalId = recipe.value(QStringLiteral("approval")).toString();
    r.approver = recipe.value(QStringLiteral("approver")).toString();
    const QString statusText = json.value(QStringLiteral("status")).toString();
    const auto status = unitStatusFromName(statusText);
    if (!status)
        return fail(tr("unknown unit status \"%1\"").arg(statusText));
    r.status = *status;
    r.attempt = json.value(QStringLiteral("attempt")).toInt(); // absent in older files: 0
    r.failureReason = json.value(QStringLiteral("failureReason")).toString();
    for (const QJsonValue& v : json.value(QStringLiteral("drives")).toArray()) {
        const QJsonObject o = v.toObject();
        UnitDrive d;
        d.machineNumber = o.value(QStringLiteral("machineNumber")).toInt();
        d.model = o.value(QStringLiteral("model")).toString();
        d.variant = o.value(QStringLiteral("variant")).toString();
        d.firmware = o.value(QStringLiteral("firmware")).toString();
        const QString source = o.value(QStringLiteral("variantSource")).toString();
        const std::optional<VariantSource> known = variantSourceFromName(source);
        if (!known)
            return fail(tr("unknown variant source \"%1\"").arg(source));
        d.variantSource = *known;
        d.variantProof = o.value(QStringLiteral("variantProof")).toString();
        r.drives.append(d);
    }
    for (const QJsonValue& v : json.value(QStringLiteral("writtenValues")).toArray()) {
        const QJsonObject o = v.toObject();
        r.writtenValues.append({o.value(QStringLiteral("machineNumber")).toInt(),
                                o.value(QStringLiteral("parameter")).toString(),
                                o.value(QStringLiteral("label")).toString(),
                                o.value(QStringLiteral("value")).toString(),
                                o.value(QStringLiteral("written")).toBool(),
                                o.value(QStringLiteral("verified")).toBool(),
                                o.value(QStringLiteral("readBack")).toString()});
    }
    for (const QJsonValue& v : json.value(QStringLiteral("measurements")).toArray()) {
        const QJsonObject o = v.toObject();
        Measurement m;
        m.machineNumber = o.value(QStringLiteral("machineNumber")).toInt();
        m.step = o.value(QStringLiteral("step")).toString();
        m.quantity = o.value(QStringLiteral("quantity")).toString();
        m.value = o.value(QStringLiteral("value")).toDouble();
        m.unit = o.value(QStringLiteral("unit")).toString();
        m.lower = numberOrNothing(o.value(QStringLiteral("lower")));
        m.upper = numberOrNothing(o.value(QStringLiteral("upper")));
        m.pass = o.value(QStringLiteral("verdict")).toString() == QLatin1String("pass");
        r.measurements.append(m);
    }
    for (const QJsonValue& v : json.value(QStringLiteral("traffic")).toArray())
        r.traffic.append(v.toString());
    return r;
}

std::optional<UnitRecord> UnitRecordJson::fromBytes(const QByteArray& data, QString* error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(data, &parseError);
    if (!doc.isObject()) {
        if (error)
            *error = tr("not JSON: %1").arg(parseError.errorString());
        return std::nullopt;
    }
    return fromJson(doc.object(), error);
}

} // namespace opentop
