#include "session/DeviceInfo.h"

#include "profile/ProfileRegistry.h"

#include <QCoreApplication>

namespace opentop {

QString DeviceInfo::hexText(int slave)
{
    return QStringLiteral("%1h")
        .arg(slave, 2, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1Char('H'), QLatin1Char('h'));
}

QString DeviceInfo::switchText(int slave)
{
    return QStringLiteral("SW1=%1 SW2=%2")
        .arg(QString::number((slave >> 4) & 0xF, 16).toUpper(),
             QString::number(slave & 0xF, 16).toUpper());
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
