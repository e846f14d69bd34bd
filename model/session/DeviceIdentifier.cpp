#include "model/session/DeviceIdentifier.h"

#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "transport/ModbusClient.h"

#include <QRegularExpression>

namespace opentop {

DeviceIdentifier::DeviceIdentifier(ModbusClient* client, const ProfileRegistry& registry,
                                   QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
{
}

void DeviceIdentifier::identify(int slave, Done done, int timeoutMs)
{
    tryProfile(slave, 0, std::move(done), timeoutMs);
}

void DeviceIdentifier::tryProfile(int slave, int profileIndex, Done done, int timeoutMs)
{
    const QVector<Profile>& profiles = m_registry.profiles();
    if (profileIndex >= profiles.size()) {
        DeviceInfo info;
        info.slave = slave;
        info.state = DeviceInfo::State::Unidentified;
        info.detail = tr("answers, but none of the device profiles matches");
        done(info);
        return;
    }
    const IdentifyRule& rule = profiles[profileIndex].identify;
    ModbusRequest request =
        rule.function == 4 ? ModbusRequest::readInput(quint8(slave), rule.address, rule.count)
                           : ModbusRequest::readHolding(quint8(slave), rule.address, rule.count);
    request.timeoutMs = timeoutMs;
    request.priority = ModbusRequest::Priority::User;
    m_client->submit(request, this,
                     [this, slave, profileIndex, done, timeoutMs](const ModbusResult& r) {
                         const DeviceInfo info = interpret(slave, profileIndex, r);
                         // A device that refuses this family's read is another family: ask the next
                         // profile. Silence means nobody is there; asking again would only cost
                         // time.
                         if (info.state == DeviceInfo::State::Unidentified)
                             tryProfile(slave, profileIndex + 1, done, timeoutMs);
                         else
                             done(info);
                     });
}

DeviceInfo DeviceIdentifier::interpret(int slave, int profileIndex,
                                       const ModbusResult& result) const
{
    const Profile& profile = m_registry.profiles()[profileIndex];
    DeviceInfo info;
    info.slave = slave;
    switch (result.error) {
    case ModbusError::Ok:
        break;
    case ModbusError::Timeout:
    case ModbusError::Cancelled:
        info.state = DeviceInfo::State::Absent;
        info.detail = result.errorText();
        return info;
    case ModbusError::CrcError:
    case ModbusError::WrongSlave:
    case ModbusError::MalformedReply:
        info.state = DeviceInfo::State::Garbled;
        info.detail = result.errorText();
        return info;
    case ModbusError::Exception:
        info.state = DeviceInfo::State::Unidentified;
        info.detail = result.errorText();
        return info;
    default:
        info.state = DeviceInfo::State::Unknown;
        info.detail = result.errorText();
        return info;
    }
    const IdentifyRule& rule = profile.identify;
    auto slice = [&](const QString& name) -> std::pair<const ParameterMeta*, QVector<quint16>> {
        const ParameterMeta* m = profile.parameter(name);
        if (!m)
            return {nullptr, {}};
        return {m, result.registers.mid(m->address - rule.address, m->registerCount)};
    };
    const auto [nameMeta, nameRegs] = slice(rule.nameParameter);
    if (nameMeta)
        info.name = ValueCodec::decode(*nameMeta, nameRegs).text;
    if (!rule.nameMatch.isEmpty() &&
        !QRegularExpression(rule.nameMatch).match(info.name).hasMatch()) {
        info.state = DeviceInfo::State::Unidentified;
        info.detail = tr("device name \"%1\" is not a %2").arg(info.name, profile.name);
        return info;
    }
    const auto [versionMeta, versionRegs] = slice(rule.versionParameter);
    if (versionMeta && !versionRegs.isEmpty()) {
        const quint16 v = versionRegs.first();
        info.firmware = QStringLiteral("%1.%2").arg(v >> 8).arg(v & 0xFF);
    }
    info.state = DeviceInfo::State::Present;
    info.family = profile.family;
    info.identifyRegisters = result.registers;
    // A family of one model: the device's own name says which ("DCPID-20A").
    info.model = profile.variants.isEmpty() && !info.name.isEmpty() ? info.name : profile.name;
    for (const ProfileVariant& variant : profile.variants) {
        if (!variant.nameMatch.isEmpty() && info.name.startsWith(variant.nameMatch)) {
            info.variant = variant.id;
            info.model = variant.model;
        }
    }
    if (info.variant.isEmpty() && !profile.variants.isEmpty())
        info.detail = tr("the variant cannot be read from the device; choose it");
    return info;
}

} // namespace opentop
