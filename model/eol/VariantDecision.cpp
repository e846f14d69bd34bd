#include "model/eol/VariantDecision.h"

#include "model/profile/Profile.h"

namespace opentop {

QString VariantDecision::modelOf(const Profile& profile, const QString& variant)
{
    const ProfileVariant* v = profile.variant(variant);
    return v ? v->model : variant;
}

QString VariantDecision::allowedText(const Profile& profile, const RecipePosition& position)
{
    QStringList models;
    for (const QString& v : position.variants)
        models << modelOf(profile, v);
    return models.join(QStringLiteral(", "));
}

VariantDecision::Decision VariantDecision::decide(const Profile& profile,
                                                  const RecipePosition& position,
                                                  const Evidence& evidence)
{
    Decision d;
    const QStringList& allowed = position.variants;
    auto fail = [&d](const QString& why) {
        d.ok = false;
        d.failure = why;
        return d;
    };
    if (profile.variants.isEmpty()) {
        d.ok = true; // a family without variants: nothing to know
        return d;
    }
    const bool probed = evidence.probe && evidence.probe->proven();
    if (evidence.probe && evidence.probe->outcome == VariantProber::Result::Outcome::Disturbed)
        return fail(
            tr("the variant probe left the drive changed: %1").arg(evidence.probe->problem));

    if (!evidence.reported.isEmpty()) {
        d.variant = evidence.reported;
        d.source = VariantSource::Read;
        d.proof = tr("reported by the drive");
    } else if (probed && evidence.probe->variants.size() == 1) {
        d.variant = evidence.probe->variants.first();
        d.source = VariantSource::Probed;
        d.proof = evidence.probe->proof;
    } else if (probed && evidence.probe->variants.contains(evidence.asserted)) {
        // The probe narrowed it to a group; the person named one of the group.
        d.variant = evidence.asserted;
        d.source = VariantSource::Confirmed;
        d.proof = tr("%1; named by %2").arg(evidence.probe->proof, evidence.operatorName);
    } else if (!probed && !evidence.asserted.isEmpty()) {
        d.variant = evidence.asserted;
        d.source = VariantSource::Confirmed;
        d.proof = tr("given for the unit by %1 (eol run --variant)").arg(evidence.operatorName);
    } else if (!probed && allowed.size() == 1 &&
               position.variantProof == QLatin1String("operator")) {
        d.variant = allowed.first();
        d.source = VariantSource::Confirmed;
        d.proof = tr("confirmed by the operator %1 (the recipe asks the operator)")
                      .arg(evidence.operatorName);
    } else if (!probed && allowed.size() == 1 && position.variantProof.isEmpty()) {
        d.variant = allowed.first();
        d.source = VariantSource::Assumed;
        d.proof = tr("the recipe's only variant, not proven on the bus");
    } else if (!probed && allowed.isEmpty() && position.variantProof != QLatin1String("required")) {
        d.ok = true; // any variant will do, and none is known: none is recorded
        return d;
    } else {
        QString why = evidence.probe && !evidence.probe->problem.isEmpty()
                          ? evidence.probe->problem
                          : tr("the family has no variant probe");
        if (probed)
            why = tr("the probe leaves %1 (%2)")
                      .arg(evidence.probe->variants.join(QStringLiteral(", ")),
                           evidence.probe->proof);
        return fail(
            allowed.isEmpty()
                ? tr("the drive does not report its variant and it was not proven (%1)").arg(why)
                : tr("the drive does not report its variant and it was not proven (%1); "
                     "the recipe allows %2 and needs proof")
                      .arg(why, allowedText(profile, position)));
    }

    // What was found against what the person said and what the recipe allows.
    if (!evidence.asserted.isEmpty() && evidence.asserted != d.variant)
        return fail(
            tr("the drive is a %1 (%2), but %3 was given for it")
                .arg(modelOf(profile, d.variant), d.proof, modelOf(profile, evidence.asserted)));
    if (!allowed.isEmpty() && !allowed.contains(d.variant))
        return fail(tr("a %1 (%2), the recipe allows %3")
                        .arg(modelOf(profile, d.variant), d.proof, allowedText(profile, position)));
    d.ok = true;
    return d;
}

} // namespace opentop
