#include "model/eol/CommLossArm.h"

#include "model/ModelLog.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

namespace opentop {

namespace {
const QString kRole = QStringLiteral("commLossTime");
} // namespace

CommLossArm::CommLossArm(DeviceSession* session)
    : m_session(session)
{
}

bool CommLossArm::applies() const
{
    return RoleEvaluator::parameter(m_session->profile(), kRole) != nullptr;
}

void CommLossArm::arm(std::function<void(const QString& error)> done)
{
    const ParameterMeta* loss = RoleEvaluator::parameter(m_session->profile(), kRole);
    m_session->read(loss->name, [this, loss, done](const DeviceSession::Outcome& r) {
        if (!r.ok) {
            done(tr("cannot read %1: %2").arg(loss->label, r.error));
            return;
        }
        m_before = ValueCodec::formatNumber(r.value.number, loss->spec.decimals);
        DeviceSession::WriteOptions options;
        options.explicitCommand = true; // the station's safety while its motor turns
        m_session->write(
            loss->name, ValueCodec::formatNumber(kSeconds, 1), options,
            [this, loss, done](const DeviceSession::Outcome& w) {
                if (!w.ok) {
                    m_before.clear();
                    done(tr("the communication-loss stop cannot be armed (%1 = %2 s): %3; the "
                            "motor is not started without it")
                             .arg(loss->label, ValueCodec::formatNumber(kSeconds, 1), w.error));
                    return;
                }
                done(QString());
            });
    });
}

void CommLossArm::disarm(std::function<void()> then)
{
    const ParameterMeta* loss = RoleEvaluator::parameter(m_session->profile(), kRole);
    if (!loss || m_before.isEmpty()) {
        then();
        return;
    }
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    m_session->write(loss->name, std::exchange(m_before, QString()), options,
                     [then](const DeviceSession::Outcome& w) {
                         if (!w.ok)
                             qCWarning(lcModel)
                                 << "communication-loss stop not restored" << w.error;
                         then();
                     });
}

} // namespace opentop
