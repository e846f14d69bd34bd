#include "model/session/SettingCheck.h"

#include "model/profile/ValueCodec.h"
#include "model/session/DependentValues.h"
#include "model/session/SerialLock.h"

namespace opentop {

SettingCheck SettingCheck::of(const Profile& profile, const ParameterMeta& meta,
                              const QString& text, const ValueContext& context,
                              const QStringList& companions)
{
    SettingCheck c;
    const ValueCodec::Encoded e = ValueCodec::encodeText(meta, text, context);
    if (!e.ok) {
        c.error = e.error;
        return c;
    }
    c.ok = true;
    c.registers = e.registers;
    c.raw = qint64(e.raw);
    c.warning = e.warning;
    c.lock = SerialLock::warning(profile, meta, c.raw, context);
    c.dependent = DependentValues::problem(profile, meta, c.raw, context, companions);
    return c;
}

ValueContext SettingCheck::overlay(const ValueContext& base,
                                   std::function<std::optional<qint64>(const QString&)> pending)
{
    ValueContext context = base;
    const auto drive = base.parameterRaw;
    context.parameterRaw = [pending = std::move(pending),
                            drive](const QString& name) -> std::optional<qint64> {
        if (const std::optional<qint64> v = pending(name))
            return v;
        return drive ? drive(name) : std::nullopt;
    };
    return context;
}

} // namespace opentop
