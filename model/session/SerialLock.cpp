#include "model/session/SerialLock.h"

#include <QCoreApplication>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::SerialLock", text);
}

QString labelOf(const ParameterMeta& meta, qint64 raw)
{
    for (const EnumOption& o : meta.spec.options) {
        if (o.value == raw)
            return QStringLiteral("%1 (%2)").arg(o.label).arg(raw);
    }
    return QString::number(raw);
}

} // namespace

bool SerialLock::locks(const Profile& profile, const ParameterMeta& meta, qint64 raw)
{
    const ProfileRole* role = profile.role(QStringLiteral("serialLock"));
    return role && role->parameter == meta.name && raw != 0;
}

QString SerialLock::warning(const Profile& profile, const ParameterMeta& meta, qint64 raw,
                            const ValueContext& context)
{
    if (!locks(profile, meta, raw))
        return QString();
    const QString name = context.nameFor(meta.name);
    // Undo (errata DC-19): the manual gives no unlock; an unstored value is lost at power-off,
    // and in potentiometer/analog control the port is fixed at 9600 8E1, address 1.
    return tr("%1 = %2 prohibits configuration over the serial interface: OpenTOP may then no "
              "longer be able to change this drive's settings over the serial line it talks on. "
              "To undo it: write %1 = %3 again if the drive still accepts it; while it is not "
              "stored, switch the drive off and on; otherwise switch the controller to "
              "potentiometer/analog control, connect at 9600 bit/s, 8E1, address 1 and write "
              "%1 = %3 there.")
        .arg(name, labelOf(meta, raw), labelOf(meta, 0));
}

} // namespace opentop
