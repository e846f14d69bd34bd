// libFuzzer harness: the profile loader (ProfileLoader::loadJson) on arbitrary bytes.
#include "model/profile/ProfileLoader.h"
#include <QByteArray>
#include <QString>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    QString error;
    const auto profile =
        opentop::ProfileLoader::loadJson(bytes, QStringLiteral("fuzz.json"), &error);
    if (!profile && error.isEmpty())
        __builtin_trap(); // a refusal must say why
    // OPENTOP_FUZZ_EXPLAIN=1 ./FuzzProfileLoader FILE: why a seed is refused (to keep seeds valid)
    static const bool explain = std::getenv("OPENTOP_FUZZ_EXPLAIN") != nullptr;
    if (explain)
        std::fprintf(stderr, "%s\n", profile ? "accepted" : qPrintable(error));
    return 0;
}
