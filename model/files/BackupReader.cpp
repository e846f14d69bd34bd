#include "model/files/BackupReader.h"

#include "model/files/BackupValidator.h"
#include "model/session/DeviceSession.h"

#include <QElapsedTimer>
#include <QPointer>
#include <memory>

namespace opentop {

BackupReader::BackupReader(DeviceSession* session, QObject* parent)
    : QObject(parent)
    , m_session(session)
{
}

QStringList BackupReader::settingNames(const Profile& profile)
{
    QStringList names;
    for (const ParameterMeta& p : profile.parameters) {
        if (p.backup && p.isReadable() && p.isWritable())
            names << p.name;
    }
    return names;
}

void BackupReader::read(Done done)
{
    const QStringList settings = settingNames(m_session->profile());
    QStringList names = settings;
    // Name and firmware: identification has usually just read them into the session.
    for (const ParameterMeta& p : m_session->profile().parameters) {
        if (p.kind == QLatin1String("info") && p.isReadable() && !m_session->hasCached(p.name))
            names << p.name;
    }
    auto timer = std::make_shared<QElapsedTimer>();
    timer->start();
    QPointer<BackupReader> self(this);
    m_session->readMany(names, [self, settings, timer,
                                done](const DeviceSession::ReadManyOutcome& outcome) {
        if (!self)
            return;
        DeviceSession* session = self->m_session;
        const Profile& profile = session->profile();
        Result result;
        result.requests = outcome.requests;
        result.parameters = settings.size();
        for (const QString& name : outcome.order) {
            const DeviceSession::Outcome o = outcome.results.value(name);
            if (!o.ok || !session->hasCached(name))
                result.failures << QStringLiteral("%1: %2").arg(name, o.error);
        }
        BackupDevice& device = result.device;
        device.slave = session->slave();
        device.family = profile.family;
        device.variant = session->variant();
        const ProfileVariant* variant = profile.variant(device.variant);
        device.model = variant ? variant->model : profile.name;
        device.name = session->cachedValue(profile.identify.nameParameter).text;
        device.machineName = session->machineName();
        if (session->hasCached(profile.identify.versionParameter)) {
            const quint16 v = session->cachedRegisters(profile.identify.versionParameter).value(0);
            device.firmware = QStringLiteral("%1.%2").arg(v >> 8).arg(v & 0xFF);
        }
        for (const QString& name : settings) {
            if (!session->hasCached(name))
                continue;
            device.parameters << BackupParameter{name, session->cachedRegisters(name)};
        }
        // The same check a file gets when it is loaded, with every value of the pass known (the
        // allowed codes of an input function depend on the control mode): a backup that could
        // not be loaded again is no backup.
        result.disallowed = BackupValidator::checkValues(
            profile, device, device.variant, BackupValidator::UnknownVariant::AnyMayFit);
        result.elapsedMs = timer->elapsed();
        result.ok = result.failures.isEmpty() && result.disallowed.isEmpty();
        done(result);
    });
}

} // namespace opentop
