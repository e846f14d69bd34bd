// libFuzzer harness: the recipe file reader (RecipeFile::fromJson) on arbitrary bytes, and the
// checker on whatever it accepts. Any crash, leak or sanitizer report is a defect; a refusal
// with a reason is the expected outcome.
#include "model/eol/RecipeChecker.h"
#include "model/eol/RecipeFile.h"
#include "model/files/BackupFile.h"
#include "model/profile/ProfileRegistry.h"
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <cstddef>
#include <cstdint>

namespace {

void readAndCheck(const QByteArray& bytes)
{
    QString error;
    QString checksum;
    const auto recipe = opentop::RecipeFile::fromJson(bytes, &error, &checksum);
    if (recipe) {
        // an accepted file must write back out and read again as the same recipe
        const QByteArray again = opentop::RecipeFile::toJson(*recipe);
        QString error2;
        QString checksum2;
        const auto reread = opentop::RecipeFile::fromJson(again, &error2, &checksum2);
        if (!reread || checksum2 != opentop::RecipeFile::checksumOf(*recipe))
            __builtin_trap();
        // the checker judges anything the reader accepts; every problem says what and where
        const opentop::RecipeChecker checker(opentop::ProfileRegistry::builtIn());
        for (const opentop::RecipeProblem& p : checker.check(*recipe)) {
            if (p.message.isEmpty() || p.path.isEmpty())
                __builtin_trap();
        }
    } else if (error.isEmpty()) {
        __builtin_trap(); // a refusal must say why
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    readAndCheck(bytes);
    // A mutated file almost never keeps a matching checksum: read it again re-signed, so that
    // the fuzzer reaches the entries behind the checksum and the checker.
    const QJsonDocument document = QJsonDocument::fromJson(bytes);
    if (document.isObject()) {
        QJsonObject root = document.object();
        root.remove(QStringLiteral("checksum"));
        root.insert(QStringLiteral("checksum"), opentop::BackupFile::checksumOf(root));
        readAndCheck(QJsonDocument(root).toJson(QJsonDocument::Compact));
    }
    return 0;
}
