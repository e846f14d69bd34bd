// libFuzzer harness: the backup file reader (BackupFile::fromJson) on arbitrary bytes, and again
// on the same bytes re-signed. Any crash, leak or sanitizer report is a defect; a refusal with a
// reason is the expected outcome.
#include "model/files/BackupFile.h"
#include "model/profile/ProfileRegistry.h"
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <cstddef>
#include <cstdint>

namespace {

void readBack(const QByteArray& bytes)
{
    QString error;
    const auto file =
        opentop::BackupFile::fromJson(bytes, opentop::ProfileRegistry::builtIn(), &error);
    if (file) {
        // an accepted file must write back out and read again as the same settings
        const QByteArray again = file->toJson(opentop::ProfileRegistry::builtIn());
        QString error2;
        if (!opentop::BackupFile::fromJson(again, opentop::ProfileRegistry::builtIn(), &error2))
            __builtin_trap();
    } else if (error.isEmpty()) {
        __builtin_trap(); // a refusal must say why
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    readBack(bytes);
    // A mutated file almost never keeps a matching checksum, so nearly every input would stop
    // there: read it again re-signed, so that the fuzzer reaches the drives and settings behind
    // the checksum (as FuzzRecipeFile does for recipes).
    const QJsonDocument document = QJsonDocument::fromJson(bytes);
    if (document.isObject()) {
        QJsonObject root = document.object();
        root.remove(QStringLiteral("checksum"));
        root.insert(QStringLiteral("checksum"), opentop::BackupFile::checksumOf(root));
        readBack(QJsonDocument(root).toJson(QJsonDocument::Compact));
    }
    return 0;
}
