#include "model/files/BackupFileParser.h"

#include "model/bus/DriveName.h"
#include "model/files/BackupValidator.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>
#include <cmath>

namespace opentop {

namespace {

QString shown(const QJsonValue& value)
{
    const QByteArray wrapped = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(wrapped.mid(1, wrapped.size() - 2));
}

} // namespace

BackupFileParser::BackupFileParser(const ProfileRegistry& registry)
    : m_registry(registry)
{
}

bool BackupFileParser::fail(const QString& message)
{
    if (m_error.isEmpty())
        m_error = message;
    return false;
}

std::optional<BackupFile> BackupFileParser::parse(const QByteArray& data, QString* error)
{
    m_error.clear();
    auto refuse = [&](const QString& message) -> std::optional<BackupFile> {
        fail(message);
        if (error)
            *error = m_error;
        return std::nullopt;
    };
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(data, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return refuse(tr("not a JSON file: %1 at byte %2")
                          .arg(parseError.errorString())
                          .arg(parseError.offset));
    if (!document.isObject())
        return refuse(tr("not an OpenTOP backup file: the JSON is not an object"));
    QJsonObject root = document.object();
    if (!checkHeader(root))
        return refuse(m_error);

    BackupFile file;
    file.tool = root.value(QStringLiteral("tool")).toString();
    file.created =
        QDateTime::fromString(root.value(QStringLiteral("created")).toString(), Qt::ISODate);
    if (!file.created.isValid())
        return refuse(tr("\"created\" is not an ISO 8601 date and time"));
    const QJsonObject connection = root.value(QStringLiteral("connection")).toObject();
    file.connection.kind = connection.value(QStringLiteral("kind")).toString();
    file.connection.port = connection.value(QStringLiteral("port")).toString();
    file.connection.host = connection.value(QStringLiteral("host")).toString();
    file.connection.sim = connection.value(QStringLiteral("sim")).toString();
    file.connection.baud = connection.value(QStringLiteral("baud")).toInt();
    file.connection.parity = connection.value(QStringLiteral("parity")).toString();
    file.connection.stopBits = connection.value(QStringLiteral("stopBits")).toInt(1);

    const QJsonValue devices = root.value(QStringLiteral("devices"));
    if (!devices.isArray() || devices.toArray().isEmpty())
        return refuse(tr("the file holds no drives (\"devices\" must be a non-empty list)"));
    QSet<int> slaves;
    const QJsonArray list = devices.toArray();
    for (int i = 0; i < list.size(); ++i) {
        const QString where = QStringLiteral("devices[%1]").arg(i);
        BackupDevice device;
        if (!list.at(i).isObject() || !readDevice(list.at(i).toObject(), where, &device))
            return refuse(tr("%1: not a drive").arg(where));
        if (slaves.contains(device.slave))
            return refuse(tr("machine number %1 appears twice").arg(device.slave));
        slaves.insert(device.slave);
        file.devices << device;
    }
    if (error)
        error->clear();
    return file;
}

bool BackupFileParser::checkHeader(const QJsonObject& root)
{
    const QString format = root.value(QStringLiteral("format")).toString();
    if (format != BackupFile::formatName())
        return fail(root.contains(QStringLiteral("format"))
                        ? tr("not an OpenTOP backup file (\"format\" is \"%1\", not \"%2\")")
                              .arg(format, BackupFile::formatName())
                        : tr("not an OpenTOP backup file (no \"format\": \"%1\")")
                              .arg(BackupFile::formatName()));
    const QJsonValue version = root.value(QStringLiteral("formatVersion"));
    const double v = version.toDouble(-1);
    if (!version.isDouble() || v != std::floor(v) || v < 1)
        return fail(tr("\"formatVersion\" must be a whole number from 1"));
    if (v > BackupFile::kFormatVersion)
        return fail(tr("written by a newer OpenTOP (format version %1); this version reads "
                       "format version %2")
                        .arg(v, 0, 'g', 15)
                        .arg(BackupFile::kFormatVersion));
    const QString checksum = root.value(QStringLiteral("checksum")).toString();
    if (!checksum.startsWith(QLatin1String("sha256:")))
        return fail(tr("the file has no checksum (\"checksum\": \"sha256:…\"); it was not "
                       "written by OpenTOP or was changed afterwards"));
    QJsonObject body = root;
    body.remove(QStringLiteral("checksum"));
    if (BackupFile::checksumOf(body) != checksum.toLower())
        return fail(tr("the file was changed after it was written (checksum mismatch)"));
    return true;
}

bool BackupFileParser::readDevice(const QJsonObject& object, const QString& where,
                                  BackupDevice* device)
{
    const QJsonValue slave = object.value(QStringLiteral("slave"));
    device->slave = slave.toInt(-1);
    if (!slave.isDouble() || device->slave < 1 || device->slave > 247)
        return fail(tr("%1: \"slave\" must be a machine number 1–247").arg(where));
    const QString at = tr("%1 (machine number %2)").arg(where).arg(device->slave);
    device->family = object.value(QStringLiteral("family")).toString();
    const Profile* profile = m_registry.family(device->family);
    if (!profile)
        return fail(tr("%1: unknown family \"%2\"; known: %3")
                        .arg(at, device->family, m_registry.families().join(QStringLiteral(", "))));
    const QJsonValue variant = object.value(QStringLiteral("variant"));
    device->variant = variant.toString();
    if (!variant.isNull() && !variant.isUndefined() && !variant.isString())
        return fail(tr("%1: \"variant\" must be text or null").arg(at));
    if (!device->variant.isEmpty() && !profile->variant(device->variant)) {
        QStringList known;
        for (const ProfileVariant& v : profile->variants)
            known << v.id;
        return fail(tr("%1: unknown variant \"%2\" of family %3; known: %4")
                        .arg(at, device->variant, device->family,
                             known.isEmpty() ? tr("none") : known.join(QStringLiteral(", "))));
    }
    device->model = object.value(QStringLiteral("model")).toString();
    device->firmware = object.value(QStringLiteral("firmware")).toString();
    device->name = object.value(QStringLiteral("name")).toString();
    const QJsonValue machineName = object.value(QStringLiteral("machineName"));
    if (!machineName.isUndefined()) {
        if (!machineName.isString())
            return fail(tr("%1: \"machineName\" must be text").arg(at));
        if (const QString problem = DriveName::problem(machineName.toString()); !problem.isEmpty())
            return fail(tr("%1: \"machineName\": %2").arg(at, problem));
        device->machineName = DriveName::cleaned(machineName.toString());
    }
    const QJsonValue parameters = object.value(QStringLiteral("parameters"));
    if (!parameters.isArray())
        return fail(tr("%1: \"parameters\" must be a list").arg(at));
    const QJsonArray list = parameters.toArray();
    for (int i = 0; i < list.size(); ++i) {
        BackupParameter p;
        if (!readParameter(*profile, list.at(i).toObject(),
                           QStringLiteral("%1 parameters[%2]").arg(at).arg(i), &p))
            return false;
        device->parameters << p;
    }
    const QStringList problems = BackupValidator::checkStructure(*profile, *device);
    if (!problems.isEmpty())
        return fail(at + QStringLiteral(": ") + problems.join(QStringLiteral("; ")));
    return checkValues(*profile, *device, at, list);
}

bool BackupFileParser::readParameter(const Profile& profile, const QJsonObject& object,
                                     const QString& where, BackupParameter* parameter)
{
    parameter->name = object.value(QStringLiteral("name")).toString();
    if (parameter->name.isEmpty())
        return fail(tr("%1: no \"name\"").arg(where));
    const QJsonValue registers = object.value(QStringLiteral("registers"));
    if (!registers.isArray())
        return fail(tr("%1 %2: \"registers\" must be a list").arg(where, parameter->name));
    for (const QJsonValue& r : registers.toArray()) {
        const double v = r.toDouble(-1);
        if (!r.isDouble() || v < 0 || v > 65535 || v != std::floor(v))
            return fail(tr("%1 %2: registers must be numbers 0–65535").arg(where, parameter->name));
        parameter->registers << quint16(v);
    }
    const ParameterMeta* meta = profile.parameter(parameter->name);
    const QString address = object.value(QStringLiteral("address")).toString();
    if (meta && address.compare(meta->addressText(), Qt::CaseInsensitive) != 0)
        return fail(tr("%1 %2: address \"%3\", but the %4 profile has it at %5")
                        .arg(where, parameter->name, address, profile.family, meta->addressText()));
    return true;
}

bool BackupFileParser::checkValues(const Profile& profile, const BackupDevice& device,
                                   const QString& where, const QJsonArray& parameters)
{
    // The value beside the registers must say the same: someone who edits one and not the
    // other gets a refusal, not a guess which of the two was meant.
    const ValueContext context = device.context(profile);
    for (int i = 0; i < parameters.size(); ++i) {
        const BackupParameter& p = device.parameters.at(i);
        const ParameterMeta& meta = *profile.parameter(p.name);
        const QJsonValue expected = BackupFile::valueOf(meta, p.registers, context);
        const QJsonValue given = parameters.at(i).toObject().value(QStringLiteral("value"));
        bool same = given.type() == expected.type();
        if (same && expected.isDouble()) {
            const double a = given.toDouble();
            const double b = expected.toDouble();
            same = std::fabs(a - b) <= 1e-6 * std::max(1.0, std::fabs(b));
        } else if (same) {
            same = given == expected;
        }
        if (!same)
            return fail(tr("%1: %2: \"value\" %3 does not match its registers (%4)")
                            .arg(where, p.name, shown(given),
                                 ValueCodec::format(meta, device.value(profile, p.name), context)));
    }
    const QStringList problems = BackupValidator::checkValues(
        profile, device, device.variant, BackupValidator::UnknownVariant::AnyMayFit);
    if (!problems.isEmpty())
        return fail(where + QStringLiteral(": ") + problems.join(QStringLiteral("; ")));
    return true;
}

} // namespace opentop
