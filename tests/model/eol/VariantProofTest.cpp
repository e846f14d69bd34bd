// A drive that reports only "DBU" proves its variant on the bus before anything is written: the
// profile's probe (the speed lower limit at 280 r/min: a DBU200 takes it, a DBU400 refuses it),
// with every register as it was afterwards. A DBU400 at a DBU200 position never passes as a
// DBU200, and the record says how each variant was known.
#include "model/eol/EolRun.h"
#include "model/eol/VariantDecision.h"
#include "model/profile/VariantProbe.h"
#include "model/session/VariantProber.h"
#include "tests/model/DriveSimFixture.h"
#include "tests/model/eol/RecipeTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

const Profile& dbu()
{
    return *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
}

// Every register value of the simulated drive, by parameter.
QHash<QString, double> registersOf(SimDevice* device)
{
    QHash<QString, double> values;
    for (const ParameterMeta& p : device->profile().parameters)
        values.insert(p.name, device->raw(p.name).value_or(-1));
    return values;
}

class VariantProofTest : public DriveSimFixture
{
protected:
    VariantProber::Result probe(int slave)
    {
        VariantProber prober(client.get(), dbu(), *VariantProbe::of(dbu()), slave);
        return await<VariantProber::Result>(
            [&](std::function<void(const VariantProber::Result&)> done) { prober.run(done); });
    }

    UnitRecord run(const Recipe& recipe, const QHash<int, QString>& asserted = {})
    {
        EolRun::Options options;
        options.serial = QStringLiteral("SN-V1");
        options.station = QStringLiteral("line 1");
        options.operatorName = QStringLiteral("Lin");
        options.recipeChecksum = RecipeFile::checksumOf(recipe);
        options.assertedVariants = asserted;
        options.timing.pollMs = 50;
        for (const RecipePosition& p : recipe.positions)
            for (const RecipeUnitValue& u : p.unitValues)
                options.unitValues[p.machineNumber][u.name] = (u.min + u.max) / 2;
        EolRun eol(client.get(), ProfileRegistry::builtIn(), recipe, options);
        return await<UnitRecord>(
            [&eol](std::function<void(const UnitRecord&)> done) { eol.start(done); }, 60000);
    }

    static Recipe quickRecipe(const QStringList& variants)
    {
        Recipe recipe = exampleRecipe("recipe-dbu200.json");
        RecipePosition& p = recipe.positions[0];
        p.variants = variants;
        for (RecipeStep& s : p.steps)
            if (s.type == RecipeStep::Type::Hold)
                s.duration = 1;
        for (RecipeSetting& s : p.settings)
            if (s.name == QLatin1String("spno2.accel") || s.name == QLatin1String("spno2.decel"))
                s.value = 0.5;
        return recipe;
    }
};

} // namespace

TEST_F(VariantProofTest, TheProfileDescribesAProbeThatSplitsTheDbuVariants)
{
    const std::optional<VariantProbe> p = VariantProbe::of(dbu());
    ASSERT_TRUE(p);
    EXPECT_EQ(p->parameter, QStringLiteral("core.lower_limit"));
    EXPECT_EQ(p->accepting, QStringList{QStringLiteral("dbu200")});
    EXPECT_EQ(p->refusing, QStringList{QStringLiteral("dbu400")});
    // A command or a motion role's register is never a probe.
    QJsonObject motion{{QStringLiteral("parameter"), QStringLiteral("spno2.speed")},
                       {QStringLiteral("value"), 280},
                       {QStringLiteral("refusedCode"), 232}};
    EXPECT_EQ(VariantProbe::check(dbu(), motion), QString()); // a setting no role names
    motion.insert(QStringLiteral("parameter"), QStringLiteral("run.start"));
    EXPECT_NE(VariantProbe::check(dbu(), motion), QString());
    motion.insert(QStringLiteral("parameter"), QStringLiteral("core.control_priority"));
    EXPECT_NE(VariantProbe::check(dbu(), motion), QString());
    // A value every variant takes proves nothing: refused as data.
    motion.insert(QStringLiteral("parameter"), QStringLiteral("core.lower_limit"));
    motion.insert(QStringLiteral("value"), 1000);
    EXPECT_NE(VariantProbe::check(dbu(), motion), QString());
}

TEST_F(VariantProofTest, TheProbeTellsADbu200FromADbu400AndLeavesEveryRegisterAsItWas)
{
    startBus(QStringLiteral("dbu200@1,dbu400@2"));
    // Lower limits the drives' own ranges allow, not the probe's value.
    bus->device(1)->setRaw(QStringLiteral("core.lower_limit"), 260);
    bus->device(2)->setRaw(QStringLiteral("core.lower_limit"), 350);
    const QHash<QString, double> before1 = registersOf(bus->device(1));
    const QHash<QString, double> before2 = registersOf(bus->device(2));

    const VariantProber::Result r1 = probe(1);
    EXPECT_EQ(r1.outcome, VariantProber::Result::Outcome::Proven) << qPrintable(r1.problem);
    EXPECT_EQ(r1.variants, QStringList{QStringLiteral("dbu200")});
    EXPECT_TRUE(r1.proof.contains(QStringLiteral("accepted"))) << qPrintable(r1.proof);
    const VariantProber::Result r2 = probe(2);
    EXPECT_EQ(r2.outcome, VariantProber::Result::Outcome::Proven) << qPrintable(r2.problem);
    EXPECT_EQ(r2.variants, QStringList{QStringLiteral("dbu400")});
    EXPECT_TRUE(r2.proof.contains(QStringLiteral("refused"))) << qPrintable(r2.proof);

    const QHash<QString, double> after1 = registersOf(bus->device(1));
    const QHash<QString, double> after2 = registersOf(bus->device(2));
    for (auto it = before1.cbegin(); it != before1.cend(); ++it) {
        if (it.key().startsWith(QLatin1String("status.")))
            continue; // the drive's own status (the communication error code of the refusal)
        EXPECT_EQ(after1.value(it.key()), it.value()) << qPrintable(it.key());
        EXPECT_EQ(after2.value(it.key()), before2.value(it.key())) << qPrintable(it.key());
    }
    EXPECT_EQ(after1.value(QStringLiteral("core.lower_limit")), 260);
    EXPECT_EQ(after2.value(QStringLiteral("core.lower_limit")), 350);
}

TEST_F(VariantProofTest, ADbu400AtADbu200PositionNeverPassesAndNothingIsWritten)
{
    startBus(QStringLiteral("dbu400@1"));
    const QHash<QString, double> before = registersOf(bus->device(1));
    const UnitRecord r = run(quickRecipe({QStringLiteral("dbu200")}));
    EXPECT_NE(r.status, UnitStatus::Pass);
    EXPECT_TRUE(r.failureReason.contains(QStringLiteral("DBU400"))) << qPrintable(r.failureReason);
    EXPECT_TRUE(r.failureReason.contains(QStringLiteral("DBU200"))) << qPrintable(r.failureReason);
    ASSERT_EQ(r.drives.size(), 1);
    EXPECT_EQ(r.drives[0].variant, QStringLiteral("dbu400")); // never recorded as the recipe's
    EXPECT_EQ(r.drives[0].variantSource, VariantSource::Probed);
    EXPECT_TRUE(r.writtenValues.isEmpty());
    const QHash<QString, double> after = registersOf(bus->device(1));
    for (auto it = before.cbegin(); it != before.cend(); ++it) {
        if (it.key().startsWith(QLatin1String("status.")))
            continue; // the drive's own status (the communication error code of the refusal)
        EXPECT_EQ(after.value(it.key()), it.value()) << qPrintable(it.key());
    }
}

TEST_F(VariantProofTest, ADbu200IsProvenAndPassesWithTheProofOnItsRecord)
{
    startBus(QStringLiteral("dbu200@1"));
    const UnitRecord r = run(quickRecipe({QStringLiteral("dbu200")}));
    EXPECT_EQ(r.status, UnitStatus::Pass) << qPrintable(r.failureReason);
    ASSERT_EQ(r.drives.size(), 1);
    EXPECT_EQ(r.drives[0].variant, QStringLiteral("dbu200"));
    EXPECT_EQ(r.drives[0].variantSource, VariantSource::Probed);
    EXPECT_TRUE(r.drives[0].variantProof.contains(QStringLiteral("280")))
        << qPrintable(r.drives[0].variantProof);
    EXPECT_EQ(bus->device(1)->raw(QStringLiteral("core.lower_limit")).value_or(-1), 0);
}

TEST_F(VariantProofTest, AVariantGivenForTheUnitThatTheProbeContradictsFails)
{
    startBus(QStringLiteral("dbu400@1"));
    const UnitRecord r = run(quickRecipe({QStringLiteral("dbu200"), QStringLiteral("dbu400")}),
                             {{1, QStringLiteral("dbu200")}});
    EXPECT_NE(r.status, UnitStatus::Pass);
    EXPECT_TRUE(r.failureReason.contains(QStringLiteral("given"))) << qPrintable(r.failureReason);
}

// Without a probe's answer (a drive that does not answer it as the manual says, or a family
// without one), the recipe decides: assumed, confirmed, or an identity error.
TEST(VariantDecisionTest, WhatIsNotProvenIsNeverRecordedAsRead)
{
    RecipePosition one;
    one.family = QStringLiteral("dbu");
    one.variants = {QStringLiteral("dbu200")};
    VariantDecision::Evidence none;
    none.operatorName = QStringLiteral("Lin");
    VariantProber::Result unproven;
    unproven.problem = QStringLiteral("no answer");
    none.probe = unproven;

    VariantDecision::Decision d = VariantDecision::decide(dbu(), one, none);
    EXPECT_TRUE(d.ok);
    EXPECT_EQ(d.source, VariantSource::Assumed);

    one.variantProof = QStringLiteral("operator");
    d = VariantDecision::decide(dbu(), one, none);
    EXPECT_TRUE(d.ok);
    EXPECT_EQ(d.source, VariantSource::Confirmed);
    EXPECT_TRUE(d.proof.contains(QStringLiteral("Lin")));

    one.variantProof = QStringLiteral("required");
    d = VariantDecision::decide(dbu(), one, none);
    EXPECT_FALSE(d.ok);
    EXPECT_TRUE(d.failure.contains(QStringLiteral("no answer"))) << qPrintable(d.failure);
    EXPECT_TRUE(d.failure.contains(QStringLiteral("DBU200"))) << qPrintable(d.failure);

    RecipePosition two = one;
    two.variantProof.clear();
    two.variants << QStringLiteral("dbu400");
    EXPECT_FALSE(VariantDecision::decide(dbu(), two, none).ok);
    VariantDecision::Evidence given = none;
    given.asserted = QStringLiteral("dbu400");
    d = VariantDecision::decide(dbu(), two, given);
    EXPECT_TRUE(d.ok);
    EXPECT_EQ(d.variant, QStringLiteral("dbu400"));
    EXPECT_EQ(d.source, VariantSource::Confirmed);

    VariantDecision::Evidence reported;
    reported.reported = QStringLiteral("dbu400");
    d = VariantDecision::decide(dbu(), one, reported);
    EXPECT_FALSE(d.ok);
    EXPECT_EQ(d.variant, QStringLiteral("dbu400"));
    EXPECT_EQ(d.source, VariantSource::Read);
}
