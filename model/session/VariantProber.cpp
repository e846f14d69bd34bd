#include "model/session/VariantProber.h"

#include "model/ModelLog.h"
#include "model/profile/Profile.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QTimer>

namespace opentop {

VariantProber::VariantProber(ModbusClient* client, const Profile& profile,
                             const VariantProbe& probe, int slave, QObject* parent,
                             const QString& journal)
    : QObject(parent)
    , m_profile(profile)
    , m_probe(probe)
    , m_journal(journal)
    , m_port(client->settings().port)
    , m_slave(slave)
{
    // As a variant that accepts the probe value: the session's own validation lets it through,
    // and the drive itself decides.
    m_session = new DeviceSession(client, profile, slave, probe.accepting.value(0), this);
    m_session->setLabelsInMessages(true);
}

void VariantProber::run(std::function<void(const Result&)> done)
{
    m_done = std::move(done);
    const std::optional<ProbeJournal::Entry> earlier = m_journal.pending(m_port, m_slave);
    if (earlier && earlier->parameter == m_probe.parameter)
        repair(*earlier);
    else
        start();
}

void VariantProber::repair(const ProbeJournal::Entry& entry)
{
    // Only while the drive still holds the probe value: anything else was set since, by the
    // probe's own write-back or by a person, and stays.
    m_session->read(m_probe.parameter, [this, entry](const DeviceSession::Outcome& r) {
        const ParameterMeta* meta = m_profile.parameter(m_probe.parameter);
        if (!r.ok || !r.value.valid) {
            finish(Result::Outcome::Unproven, QString(),
                   tr("%1 cannot be read: %2").arg(meta->canonicalLabel, r.error));
            return;
        }
        QString error;
        if (ValueCodec::formatNumber(r.value.number, meta->spec.decimals) != entry.probe) {
            m_journal.end(m_port, m_slave, &error);
            start();
            return;
        }
        DeviceSession::WriteOptions options;
        options.verify = true;
        m_session->write(
            m_probe.parameter, entry.original, options,
            [this, entry, meta](const DeviceSession::Outcome& w) {
                if (!w.ok) {
                    finish(Result::Outcome::Disturbed, QString(),
                           tr("%1 still holds %2 from a variant probe that was "
                              "interrupted, and cannot be set back to %3 (%4): set "
                              "it to %3 before this drive is used")
                               .arg(meta->canonicalLabel, entry.probe, entry.original, w.error));
                    return;
                }
                QString ignored; // a stale entry is checked against the drive
                m_journal.end(m_port, m_slave, &ignored);
                m_repaired = tr("%1 set back from %2 to %3, left by a variant probe "
                                "that was interrupted")
                                 .arg(meta->canonicalLabel, entry.probe, entry.original);
                start();
            });
    });
}

void VariantProber::start()
{
    const ParameterMeta* meta = m_profile.parameter(m_probe.parameter);
    m_session->read(m_probe.parameter, [this, meta](const DeviceSession::Outcome& r) {
        if (!r.ok || !r.value.valid) {
            finish(Result::Outcome::Unproven, QString(),
                   tr("%1 cannot be read: %2").arg(meta->canonicalLabel, r.error));
            return;
        }
        m_original = r.value.registers;
        m_originalText = ValueCodec::formatNumber(r.value.number, meta->spec.decimals);
        probe();
    });
}

void VariantProber::probe()
{
    const ParameterMeta* meta = m_profile.parameter(m_probe.parameter);
    const QString text = ValueCodec::formatNumber(m_probe.value, meta->spec.decimals);
    // Kept before it is sent: a kill from here on is put right by the next probe.
    QString error;
    if (!m_journal.begin(m_port, m_slave, {m_probe.parameter, m_originalText, text}, &error)) {
        finish(Result::Outcome::Unproven, QString(),
               tr("not probed: the original value cannot be kept while it is (%1)").arg(error));
        return;
    }
    DeviceSession::WriteOptions options;
    options.verify = true;
    m_session->write(m_probe.parameter, text, options, [this](const DeviceSession::Outcome& w) {
        if (w.ok) {
            accepted(true);
            return;
        }
        if (w.sent && w.deviceCode == m_probe.refusedCode) {
            refused(w.deviceError);
            return;
        }
        // Anything else (no answer, another refusal, a value that did not stick) proves
        // nothing; what the drive holds now is read, and put back when it changed.
        m_session->read(m_probe.parameter, [this, w](const DeviceSession::Outcome& r) {
            if (r.ok && r.value.registers == m_original) {
                QString ignored;
                m_journal.end(m_port, m_slave, &ignored);
                finish(Result::Outcome::Unproven, QString(),
                       tr("the probe %1 was not answered as the manual says: %2")
                           .arg(m_probe.describe(m_profile), w.error));
                return;
            }
            // The drive holds the probe value only if it took it: that proves as much as an
            // answer. Anything else is written back and proves nothing.
            const ParameterMeta* param = m_profile.parameter(m_probe.parameter);
            const ValueCodec::Encoded probeValue =
                ValueCodec::encodeNumber(*param, m_probe.value, m_session->context());
            accepted(r.ok && r.value.registers == probeValue.registers);
        });
    });
}

void VariantProber::accepted(bool proves)
{
    m_variants = proves ? m_probe.accepting : QStringList();
    DeviceSession::WriteOptions options;
    options.verify = true;
    m_session->write(m_probe.parameter, m_originalText, options,
                     [this](const DeviceSession::Outcome& w) {
                         const ParameterMeta* meta = m_profile.parameter(m_probe.parameter);
                         if (!w.ok) {
                             finish(Result::Outcome::Disturbed, QString(),
                                    tr("%1 could not be set back to %2 after the variant probe "
                                       "(%3): set it to %2 before this drive is used")
                                        .arg(meta->canonicalLabel, m_originalText, w.error));
                             return;
                         }
                         checkOriginal(tr("%1 accepted, %2 written back")
                                           .arg(m_probe.describe(m_profile), m_originalText));
                     });
}

void VariantProber::refused(const QString& deviceError)
{
    m_variants = m_probe.refusing;
    checkOriginal(tr("%1 refused (%2)").arg(m_probe.describe(m_profile), deviceError));
}

void VariantProber::checkOriginal(const QString& proof)
{
    // The proof counts only with the drive as it was: its setting read once more.
    m_session->read(m_probe.parameter, [this, proof](const DeviceSession::Outcome& r) {
        const ParameterMeta* meta = m_profile.parameter(m_probe.parameter);
        if (!r.ok || r.value.registers != m_original) {
            // The entry stays: the next probe of this drive tries again.
            finish(Result::Outcome::Disturbed, proof,
                   tr("%1 does not read back as %2 after the variant probe (%3): set it to %2 "
                      "before this drive is used")
                       .arg(meta->canonicalLabel, m_originalText,
                            r.ok ? ValueCodec::formatCanonical(*meta, r.value) : r.error));
            return;
        }
        QString error;
        if (!m_journal.end(m_port, m_slave, &error))
            qCWarning(lcModel) << error; // the next probe finds the original: harmless
        if (m_variants.isEmpty()) {
            finish(Result::Outcome::Unproven, proof, tr("the probe did not decide"));
            return;
        }
        finish(Result::Outcome::Proven, proof, QString());
    });
}

void VariantProber::finish(Result::Outcome outcome, const QString& proof, const QString& problem)
{
    Result result;
    result.outcome = outcome;
    result.proof = proof;
    result.problem = problem;
    result.repaired = m_repaired;
    if (outcome == Result::Outcome::Proven)
        result.variants = m_variants;
    auto done = std::move(m_done);
    m_done = nullptr;
    if (done)
        QTimer::singleShot(0, this, [done, result] { done(result); });
}

} // namespace opentop
