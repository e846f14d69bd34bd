// libFuzzer harness: the values a user types on the command line. The first byte picks what the
// text is: a bus SPEC (BusSpec::parse), an id list (CliContext::parseIds) or a `set` value
// (ValueCodec::encodeText) for one of the built-in profiles' parameters; the rest is the text.
#include "cli/CliContext.h"
#include "model/bus/BusSpec.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include <QString>
#include <cstddef>
#include <cstdint>

using namespace opentop;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size < 2)
        return 0;
    const uint8_t kind = data[0];
    const QString text = QString::fromUtf8(reinterpret_cast<const char*>(data + 1),
                                           static_cast<qsizetype>(size - 1));
    QString error;
    switch (kind % 3) {
    case 0: {
        const auto spec = BusSpec::parse(text, &error);
        if (spec) // what was accepted prints as a spec that reads back the same
            (void)BusSpec::toString(*spec);
        else if (error.isEmpty())
            __builtin_trap();
        break;
    }
    case 1: {
        const auto ids = CliContext::parseIds(text, &error);
        if (ids) {
            for (int id : *ids)
                if (id < 1 || id > 247)
                    __builtin_trap();
        } else if (error.isEmpty()) {
            __builtin_trap();
        }
        break;
    }
    default: {
        const auto& profiles = ProfileRegistry::builtIn().profiles();
        int index = kind / 3;
        for (const Profile& profile : profiles) {
            if (index < profile.parameters.size()) {
                const ParameterMeta& meta = profile.parameters[index];
                const auto encoded = ValueCodec::encodeText(meta, text);
                if (encoded.ok) // what was accepted decodes as an allowed value
                    (void)ValueCodec::format(meta, ValueCodec::decode(meta, encoded.registers));
                else if (encoded.error.isEmpty())
                    __builtin_trap(); // a refusal must name the allowed values
                break;
            }
            index -= static_cast<int>(profile.parameters.size());
        }
        break;
    }
    }
    return 0;
}
