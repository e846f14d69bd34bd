#include "model/eol/VariantCheck.h"

#include <QTimer>

namespace opentop {

VariantCheck::VariantCheck(ModbusClient* client, const Profile& profile,
                           const RecipePosition& position, VariantDecision::Evidence evidence,
                           QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_profile(profile)
    , m_position(position)
    , m_evidence(std::move(evidence))
{
    // A drive that says what it is is not probed.
    if (m_evidence.reported.isEmpty())
        m_probe = VariantProbe::of(profile);
}

QString VariantCheck::probeText() const
{
    return m_probe ? tr("proving the variant (%1)").arg(m_probe->describe(m_profile)) : QString();
}

void VariantCheck::run(std::function<void(const VariantDecision::Decision&)> done)
{
    if (!m_probe) {
        const VariantDecision::Decision d =
            VariantDecision::decide(m_profile, m_position, m_evidence);
        QTimer::singleShot(0, this, [done, d] { done(d); });
        return;
    }
    auto* prober = new VariantProber(m_client, m_profile, *m_probe, m_position.machineNumber, this);
    prober->run([this, prober, done](const VariantProber::Result& r) {
        prober->deleteLater();
        m_evidence.probe = r;
        VariantDecision::Decision d = VariantDecision::decide(m_profile, m_position, m_evidence);
        // The record says when an earlier, interrupted probe had to be put right.
        if (!r.repaired.isEmpty())
            d.proof = d.proof.isEmpty() ? r.repaired : d.proof + QStringLiteral("; ") + r.repaired;
        done(d);
    });
}

} // namespace opentop
