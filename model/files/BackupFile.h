#pragma once

#include "model/files/BackupDevice.h"
#include "transport/ConnectionSettings.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonObject>
#include <QJsonValue>
#include <QVector>
#include <optional>

namespace opentop {

class ProfileRegistry;

// A backup file (docs/backup-format.md): versioned, human-readable JSON with one setting per
// line, several drives per file, and a checksum over the canonical compact JSON so that a file
// changed after it was written is refused rather than restored.
class BackupFile
{
    Q_DECLARE_TR_FUNCTIONS(opentop::BackupFile)
public:
    static constexpr int kFormatVersion = 1;
    // load() refuses larger files without reading them (a 247-drive backup is far smaller).
    static constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024;
    static QString formatName() { return QStringLiteral("opentop-backup"); }

    // Where the settings were read (informational: a restore uses the connection it is given).
    struct Connection
    {
        QString kind; // "serial", "tcp", "sim"
        QString port; // serial device
        QString host; // "HOST:PORT"
        QString sim;  // simulated bus spec
        int baud = 0;
        QString parity;
        int stopBits = 1;
    };

    QString tool; // "OpenTOP 0.1.0"
    QDateTime created;
    Connection connection;
    QVector<BackupDevice> devices; // by machine number

    static Connection connectionOf(const ConnectionSettings& settings);
    static QString toolName(); // "OpenTOP <version>"
    const BackupDevice* device(int slave) const;
    QVector<int> slaves() const;
    // The machine number of the file's drive to set beside drive `slave` of `family` (the
    // other side of a comparison): that drive, else the first of the family, else the first;
    // 0 when the file is empty.
    int counterpartOf(int slave, const QString& family) const;

    // The file's text: pretty-printed, keys in a fixed order, one parameter per line.
    QByteArray toJson(const ProfileRegistry& registry) const;
    // Refuses anything that is not an intact backup whose values the profiles allow; *error
    // says why (and names the drive, the parameter and the allowed values).
    static std::optional<BackupFile> fromJson(const QByteArray& data,
                                              const ProfileRegistry& registry, QString* error);
    // Atomic: the file is replaced only once the whole text has been written.
    bool save(const QString& path, const ProfileRegistry& registry, QString* error) const;
    static std::optional<BackupFile> load(const QString& path, const ProfileRegistry& registry,
                                          QString* error);

    // "sha256:<hex>" of the canonical compact JSON of `document` (which has no checksum key).
    static QString checksumOf(const QJsonObject& document);
    // The "value" written beside the registers: the engineering number (rounded to the step of
    // the scale, floats to the shortest text that gives the same float), or the text.
    static QJsonValue valueOf(const ParameterMeta& meta, const QVector<quint16>& registers,
                              const ValueContext& context);

private:
    QJsonObject toObject(const ProfileRegistry& registry) const;
};

} // namespace opentop
