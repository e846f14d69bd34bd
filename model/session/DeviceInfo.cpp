#include "model/session/DeviceInfo.h"

#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>

namespace opentop {

QString DeviceInfo::hexText(int slave)
{
    return QStringLiteral("%1h")
        .arg(slave, 2, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1Char('H'), QLatin1Char('h'));
}

QString DeviceInfo::switchText(int slave, const QString& family)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    if (const Profile* p = registry.family(family))
        return p->addressSwitches.positions(slave);
    QStringList each;
    QVector<const Profile*> possible;
    for (const Profile& p : registry.profiles()) {
        if (p.addressSwitches.notation != AddressSwitches::Notation::None && slave >= p.minSlave &&
            slave <= p.maxSlave)
            possible << &p;
    }
    for (const Profile* p : possible)
        each << (possible.size() == 1
                     ? p->addressSwitches.positions(slave)
                     : QStringLiteral("%1 %2").arg(p->family.toUpper(),
                                                   p->addressSwitches.positions(slave)));
    return each.join(QStringLiteral(" / "));
}

QString DeviceInfo::addressText(int slave, const QString& family)
{
    const Profile* p = ProfileRegistry::builtIn().family(family);
    if (p && !p->addressSwitches.showsHex())
        return switchText(slave, family);
    return hexText(slave) + QStringLiteral("  ") + switchText(slave, family);
}

QString DeviceInfo::switchHelp(const QString& family)
{
    QStringList lines;
    for (const Profile& p : ProfileRegistry::builtIn().profiles()) {
        if ((family.isEmpty() || p.family == family) && !p.addressSwitches.help.isEmpty())
            lines << QStringLiteral("%1: %2").arg(p.family.toUpper(), p.addressSwitches.help);
    }
    return lines.join(QLatin1Char('\n'));
}

QString DeviceInfo::stateText(State state)
{
    switch (state) {
    case State::Unknown:
        return QCoreApplication::translate("opentop::DeviceInfo", "not checked");
    case State::Present:
        return QCoreApplication::translate("opentop::DeviceInfo", "online");
    case State::Absent:
        return QCoreApplication::translate("opentop::DeviceInfo", "no answer");
    case State::Garbled:
        return QCoreApplication::translate("opentop::DeviceInfo",
                                           "garbled replies (duplicate machine number?)");
    case State::Unidentified:
        return QCoreApplication::translate("opentop::DeviceInfo", "unknown device");
    case State::IdentifyFailed:
        return QCoreApplication::translate("opentop::DeviceInfo",
                                           "answered, identification failed");
    }
    return QString();
}

bool DeviceInfo::variantUnknown() const
{
    if (state != State::Present || !variant.isEmpty())
        return false;
    const Profile* p = ProfileRegistry::builtIn().family(family);
    return p && !p->variants.isEmpty();
}

QString DeviceInfo::shortModel() const
{
    return variantUnknown() || model.isEmpty() ? family.toUpper() : model;
}

} // namespace opentop
