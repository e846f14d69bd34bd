#include "model/eol/EolSettingsWriter.h"

#include "model/files/RestorePlan.h"
#include "model/files/Restorer.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

namespace opentop {

EolSettingsWriter::EolSettingsWriter(DeviceSession* session, const BackupDevice& target,
                                     int machineNumber, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_target(target)
    , m_machineNumber(machineNumber)
{
}

void EolSettingsWriter::write(Done done)
{
    m_restorer = new Restorer(m_session, this);
    m_restorer->start(m_target, {}, [this, done = std::move(done)](const RestorePlan& plan) {
        m_restorer->deleteLater();
        m_restorer = nullptr;
        if (!m_dropped)
            done(written(plan));
    });
}

void EolSettingsWriter::cancel()
{
    if (m_restorer)
        m_restorer->cancel();
}

QString EolSettingsWriter::written(const RestorePlan& plan)
{
    const Profile& profile = m_session->profile();
    const ValueContext context = m_session->context();
    for (const RestorePlan::Item& item : plan.items) {
        if (item.action == RestorePlan::Item::Action::Store)
            continue;
        const ParameterMeta* meta = profile.parameter(item.parameter);
        WrittenValue w;
        w.machineNumber = m_machineNumber;
        w.parameter = item.parameter;
        // A result record holds the profile's English (canonicalLabel, formatCanonical), whatever
        // the language of the station: records of every station are read and compared together.
        w.label = meta ? meta->canonicalLabel : item.parameter;
        const BackupParameter* want = m_target.parameter(item.parameter);
        w.value = meta && want
                      ? ValueCodec::formatCanonical(
                            *meta, ValueCodec::decode(*meta, want->registers, context), context)
                      : item.fileText;
        w.written = item.action == RestorePlan::Item::Action::Write &&
                    item.status != RestorePlan::Item::Status::NotAttempted;
        w.verified = false; // proven by the read below
        m_written.append(w);
    }
    if (plan.outcome == RestorePlan::Outcome::Done)
        return QString();
    QString reason = plan.reason;
    if (reason.isEmpty())
        reason = RestorePlan::outcomeText(plan.outcome);
    for (const RestorePlan::Item& item : plan.items) {
        if (item.status == RestorePlan::Item::Status::Failed ||
            item.status == RestorePlan::Item::Status::NotConfirmed) {
            const ParameterMeta* meta = profile.parameter(item.parameter);
            reason = tr("%1: %2").arg(meta ? meta->label : item.parameter, item.error);
            break;
        }
    }
    if (!plan.problems.isEmpty())
        reason +=
            QStringLiteral(" (") + plan.problems.join(QStringLiteral("; ")) + QStringLiteral(")");
    return reason;
}

void EolSettingsWriter::verify(Done done)
{
    m_session->readMany(m_target.parameterNames(), [this, done = std::move(done)](
                                                       const DeviceSession::ReadManyOutcome& many) {
        if (m_dropped)
            return;
        const Profile& profile = m_session->profile();
        const ValueContext context = m_session->context();
        QString firstFailure;
        for (WrittenValue& w : m_written) {
            const DeviceSession::Outcome r = many.results.value(w.parameter);
            const BackupParameter* want = m_target.parameter(w.parameter);
            const ParameterMeta* meta = profile.parameter(w.parameter);
            if (!r.ok || !want || !meta) {
                w.readBack = QString();
                if (firstFailure.isEmpty())
                    firstFailure = tr("%1 cannot be read back: %2").arg(w.label, r.error);
                continue;
            }
            w.readBack = ValueCodec::formatCanonical(*meta, r.value, context);
            w.verified = r.value.registers == want->registers;
            if (!w.verified && firstFailure.isEmpty())
                firstFailure = tr("%1 does not keep its value: set to %2, reads %3")
                                   .arg(w.label, w.value, w.readBack);
        }
        done(firstFailure);
    });
}

} // namespace opentop
