#include "model/files/BackupFile.h"
#include "model/io/InputFile.h"
#include "model/io/OutputFile.h"

#include "model/files/BackupFileParser.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"

#include <QCryptographicHash>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <cmath>
#include <functional>

namespace opentop {

namespace {

// A scalar exactly as QJsonDocument writes it, so that the pretty text and the canonical
// compact text (the checksum's input) hold the same numbers.
QByteArray scalar(const QJsonValue& value)
{
    const QByteArray wrapped = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return wrapped.mid(1, wrapped.size() - 2);
}

QByteArray inlineArray(const QJsonArray& array)
{
    QByteArrayList items;
    for (const QJsonValue& v : array)
        items << scalar(v);
    return '[' + items.join(", ") + ']';
}

// Keys in the order people read them; anything else follows alphabetically.
QByteArray orderedFields(const QJsonObject& object, const QStringList& order,
                         const QByteArray& indent,
                         const std::function<QByteArray(const QString&, const QJsonValue&)>& nested)
{
    QStringList keys;
    for (const QString& k : order) {
        if (object.contains(k))
            keys << k;
    }
    for (const QString& k : object.keys()) {
        if (!keys.contains(k))
            keys << k;
    }
    QByteArrayList lines;
    for (const QString& k : keys) {
        QByteArray text = nested ? nested(k, object.value(k)) : QByteArray();
        if (text.isNull())
            text = scalar(object.value(k));
        lines << indent + scalar(k) + ": " + text;
    }
    return lines.join(",\n");
}

QByteArray parameterLine(const QJsonObject& p)
{
    static const QStringList order{QStringLiteral("name"),      QStringLiteral("address"),
                                   QStringLiteral("registers"), QStringLiteral("value"),
                                   QStringLiteral("text"),      QStringLiteral("unit")};
    QByteArrayList fields;
    QStringList keys = order;
    for (const QString& k : p.keys()) {
        if (!keys.contains(k))
            keys << k;
    }
    for (const QString& k : keys) {
        if (!p.contains(k))
            continue;
        const QJsonValue v = p.value(k);
        fields << scalar(k) + ": " + (v.isArray() ? inlineArray(v.toArray()) : scalar(v));
    }
    return '{' + fields.join(", ") + '}';
}

QByteArray pretty(const QJsonObject& root)
{
    auto deviceText = [](const QJsonObject& device) {
        return orderedFields(
            device,
            {QStringLiteral("slave"), QStringLiteral("family"), QStringLiteral("variant"),
             QStringLiteral("model"), QStringLiteral("firmware"), QStringLiteral("name"),
             QStringLiteral("machineName"), QStringLiteral("parameters")},
            "      ", [](const QString& key, const QJsonValue& v) {
                if (key != QLatin1String("parameters") || !v.isArray())
                    return QByteArray();
                QByteArrayList lines;
                for (const QJsonValue& p : v.toArray())
                    lines << "        " + parameterLine(p.toObject());
                return lines.isEmpty() ? QByteArray("[]") : "[\n" + lines.join(",\n") + "\n      ]";
            });
    };
    const QByteArray body = orderedFields(
        root,
        {QStringLiteral("format"), QStringLiteral("formatVersion"), QStringLiteral("tool"),
         QStringLiteral("created"), QStringLiteral("connection"), QStringLiteral("devices"),
         QStringLiteral("checksum")},
        "  ", [&](const QString& key, const QJsonValue& v) {
            if (key == QLatin1String("connection") && v.isObject())
                return "{\n" +
                       orderedFields(v.toObject(),
                                     {QStringLiteral("kind"), QStringLiteral("port"),
                                      QStringLiteral("host"), QStringLiteral("sim"),
                                      QStringLiteral("baud"), QStringLiteral("parity"),
                                      QStringLiteral("stopBits")},
                                     "    ", {}) +
                       "\n  }";
            if (key == QLatin1String("devices") && v.isArray()) {
                QByteArrayList devices;
                for (const QJsonValue& d : v.toArray())
                    devices << "    {\n" + deviceText(d.toObject()) + "\n    }";
                return devices.isEmpty() ? QByteArray("[]") : "[\n" + devices.join(",\n") + "\n  ]";
            }
            return QByteArray();
        });
    return "{\n" + body + "\n}\n";
}

// Digits after the point that show every multiple of `scale` exactly (0.1 -> 1, 0.01 -> 2).
int digitsOf(double scale)
{
    for (int d = 0; d < 10; ++d) {
        const double shifted = scale * std::pow(10.0, d);
        if (std::fabs(shifted - std::round(shifted)) < 1e-9 * std::max(1.0, shifted))
            return d;
    }
    return 10;
}

} // namespace

QString BackupFile::toolName()
{
    return QStringLiteral("OpenTOP ") + QStringLiteral(OPENTOP_VERSION);
}

BackupFile::Connection BackupFile::connectionOf(const ConnectionSettings& settings)
{
    Connection c;
    switch (settings.kind) {
    case ConnectionSettings::Kind::Serial:
        c.kind = QStringLiteral("serial");
        c.port = settings.port;
        break;
    case ConnectionSettings::Kind::Tcp:
        c.kind = QStringLiteral("tcp");
        c.host = QStringLiteral("%1:%2").arg(settings.host).arg(settings.tcpPort);
        break;
    case ConnectionSettings::Kind::Simulated:
        c.kind = QStringLiteral("sim");
        c.sim = settings.simSpec;
        break;
    }
    c.baud = settings.baud;
    c.parity = QString(QLatin1Char(settings.parity));
    c.stopBits = settings.stopBits;
    return c;
}

const BackupDevice* BackupFile::device(int slave) const
{
    for (const BackupDevice& d : devices) {
        if (d.slave == slave)
            return &d;
    }
    return nullptr;
}

int BackupFile::counterpartOf(int slave, const QString& family) const
{
    // The same drive when the file has it; else the file's first drive of the family (a backup
    // of another machine of the same kind); else the first: something comparable is shown.
    for (const BackupDevice& d : devices) {
        if (d.slave == slave && (family.isEmpty() || d.family == family))
            return d.slave;
    }
    for (const BackupDevice& d : devices) {
        if (!family.isEmpty() && d.family == family)
            return d.slave;
    }
    return devices.isEmpty() ? 0 : devices.first().slave;
}

QVector<int> BackupFile::slaves() const
{
    QVector<int> ids;
    for (const BackupDevice& d : devices)
        ids << d.slave;
    return ids;
}

QJsonValue BackupFile::valueOf(const ParameterMeta& meta, const QVector<quint16>& registers,
                               const ValueContext& context)
{
    const ParamValue v = ValueCodec::decode(meta, registers, context);
    if (meta.type == DataType::String)
        return v.text;
    const double scale = meta.specFor(context).scale;
    if (meta.type == DataType::F32) {
        const float f = float(v.raw);
        for (int precision = 6; precision <= 9; ++precision) {
            const double shown = QString::number(double(f) * scale, 'g', precision).toDouble();
            if (float(shown / scale) == f)
                return shown;
        }
        return v.number;
    }
    if (scale == 1.0)
        return v.raw;
    return QString::number(v.number, 'f', digitsOf(scale)).toDouble();
}

QJsonObject BackupFile::toObject(const ProfileRegistry& registry) const
{
    QJsonObject connectionObject{{QStringLiteral("kind"), connection.kind},
                                 {QStringLiteral("baud"), connection.baud},
                                 {QStringLiteral("parity"), connection.parity},
                                 {QStringLiteral("stopBits"), connection.stopBits}};
    if (!connection.port.isEmpty())
        connectionObject.insert(QStringLiteral("port"), connection.port);
    if (!connection.host.isEmpty())
        connectionObject.insert(QStringLiteral("host"), connection.host);
    if (!connection.sim.isEmpty())
        connectionObject.insert(QStringLiteral("sim"), connection.sim);
    QJsonArray deviceArray;
    for (const BackupDevice& d : devices) {
        const Profile* profile = registry.family(d.family);
        QJsonArray parameters;
        const ValueContext context = profile ? d.context(*profile) : ValueContext();
        for (const BackupParameter& p : d.parameters) {
            const ParameterMeta* meta = profile ? profile->parameter(p.name) : nullptr;
            QJsonArray registers;
            for (quint16 r : p.registers)
                registers << int(r);
            QJsonObject o{{QStringLiteral("name"), p.name},
                          {QStringLiteral("registers"), registers}};
            if (meta) {
                o.insert(QStringLiteral("address"), meta->addressText());
                o.insert(QStringLiteral("value"), valueOf(*meta, p.registers, context));
                // The profile's English, whatever the profile language: a file is an interface.
                o.insert(QStringLiteral("text"),
                         ValueCodec::formatCanonical(*meta, d.value(*profile, p.name), context));
                o.insert(QStringLiteral("unit"), meta->specFor(context).canonicalUnit);
            }
            parameters << o;
        }
        QJsonObject device{
            {QStringLiteral("slave"), d.slave},
            {QStringLiteral("family"), d.family},
            {QStringLiteral("variant"), d.variant.isEmpty() ? QJsonValue() : QJsonValue(d.variant)},
            {QStringLiteral("model"), d.model},
            {QStringLiteral("firmware"), d.firmware},
            {QStringLiteral("name"), d.name},
            {QStringLiteral("parameters"), parameters}};
        // Only when the machine has one: files of unnamed machines stay as they were.
        if (!d.machineName.isEmpty())
            device.insert(QStringLiteral("machineName"), d.machineName);
        deviceArray << device;
    }
    return QJsonObject{
        {QStringLiteral("format"), formatName()},
        {QStringLiteral("formatVersion"), kFormatVersion},
        {QStringLiteral("tool"), tool},
        {QStringLiteral("created"), created.toUTC().toString(Qt::ISODate)},
        {QStringLiteral("connection"), connectionObject},
        {QStringLiteral("devices"), deviceArray},
    };
}

QString BackupFile::checksumOf(const QJsonObject& document)
{
    const QByteArray canonical = QJsonDocument(document).toJson(QJsonDocument::Compact);
    return QStringLiteral("sha256:") +
           QString::fromLatin1(
               QCryptographicHash::hash(canonical, QCryptographicHash::Sha256).toHex());
}

QByteArray BackupFile::toJson(const ProfileRegistry& registry) const
{
    QJsonObject root = toObject(registry);
    root.insert(QStringLiteral("checksum"), checksumOf(root));
    return pretty(root);
}

std::optional<BackupFile> BackupFile::fromJson(const QByteArray& data,
                                               const ProfileRegistry& registry, QString* error)
{
    return BackupFileParser(registry).parse(data, error);
}

bool BackupFile::save(const QString& path, const ProfileRegistry& registry, QString* error) const
{
    return OutputFile::write(path, toJson(registry), error);
}

std::optional<BackupFile> BackupFile::load(const QString& path, const ProfileRegistry& registry,
                                           QString* error)
{
    QByteArray data;
    const InputFile::Status read = InputFile::read(path, kMaxFileBytes, &data, error);
    if (read == InputFile::Status::CannotOpen)
        return std::nullopt;
    if (read == InputFile::Status::TooLarge) {
        if (error)
            *error = tr("%1 is larger than %2 MB, the most a backup file may hold (a backup of "
                        "247 drives is far smaller); not a backup file")
                         .arg(path)
                         .arg(kMaxFileBytes / (1024 * 1024));
        return std::nullopt;
    }
    return fromJson(data, registry, error);
}

} // namespace opentop
