// libFuzzer harness: the backup file reader (BackupFile::fromJson) on arbitrary bytes. Any crash,
// leak or sanitizer report is a defect; a refusal with a reason is the expected outcome.
#include "model/files/BackupFile.h"
#include "model/profile/ProfileRegistry.h"
#include <QByteArray>
#include <QString>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
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
    return 0;
}
