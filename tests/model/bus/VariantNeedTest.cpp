// Issue 24: when a drive's variant must be asked, and what the question says it changes.
#include "model/bus/VariantNeed.h"
#include "model/bus/BusDrives.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "tests/model/DriveSimFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class VariantNeedTest : public DriveSimFixture
{
protected:
    // Drive 1 a DBU whose variant nobody knows, 7 a DC controller (no variants).
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1,dcpid@7"));
        drives = identifiedDrives({1, 7});
        drives->setVariant(1, QString());
        DeviceInfo unknown = drives->info(1);
        unknown.variant.clear();
        unknown.model = QStringLiteral("DBU");
        drives->update(unknown);
    }
    void TearDown() override
    {
        drives.reset();
        DriveSimFixture::TearDown();
    }
    std::unique_ptr<BusDrives> drives;
};

} // namespace

TEST_F(VariantNeedTest, AskedBeforeWhatDependsOnItAndOnlyOnce)
{
    using P = VariantNeed::Purpose;
    ASSERT_TRUE(drives->session(1)->variant().isEmpty());
    // The speeds depend on the variant; the acceleration does not.
    EXPECT_TRUE(VariantNeed::needed(*drives, 1, P::Write, {QStringLiteral("spno2.speed")}));
    EXPECT_FALSE(VariantNeed::needed(*drives, 1, P::Write, {QStringLiteral("spno2.accel")}));
    EXPECT_TRUE(VariantNeed::needed(*drives, 1, P::Backup));
    EXPECT_TRUE(VariantNeed::needed(*drives, 1, P::Start));
    // A family without variants is never asked.
    EXPECT_FALSE(VariantNeed::needed(*drives, 7, P::Start));
    // "Not known" is an answer: not asked again while connected.
    drives->declineVariant(1);
    EXPECT_FALSE(VariantNeed::needed(*drives, 1, P::Start));
}

TEST_F(VariantNeedTest, AVariantGivenIsUsedForTheEditsAlreadyMade)
{
    // 280 r/min suits a DBU200, not a DBU400: while the variant is unknown it is refused.
    DeviceParameters* p = drives->parameters(1);
    EXPECT_FALSE(p->setPending(QStringLiteral("spno2.speed"), QStringLiteral("280")).isEmpty());
    EXPECT_EQ(p->invalidNames(), QStringList{QStringLiteral("spno2.speed")});
    drives->setVariant(1, QStringLiteral("dbu200"));
    EXPECT_FALSE(VariantNeed::needed(*drives, 1, VariantNeed::Purpose::Start));
    EXPECT_TRUE(p->invalidNames().isEmpty()) << "checked again against the DBU200";
    EXPECT_EQ(p->pendingNames(), QStringList{QStringLiteral("spno2.speed")});
}

TEST_F(VariantNeedTest, TheQuestionSaysWhatTheVariantChanges)
{
    drives->setName(1, QStringLiteral("Infeed conveyor 3"));
    drives->setRememberedVariants({{1, QStringLiteral("dbu400")}});
    const QString q = VariantNeed::question(*drives, 1, VariantNeed::Purpose::Start,
                                            drives->rememberedVariant(1));
    EXPECT_TRUE(q.contains(QStringLiteral("machine number 1 (Infeed conveyor 3)")))
        << qPrintable(q);
    EXPECT_TRUE(q.contains(QStringLiteral("DBU200-D or DBU400-D4"))) << qPrintable(q);
    // Each variant as the profile describes it, and the allowed values that differ.
    EXPECT_TRUE(q.contains(QStringLiteral("24 V, 200 W"))) << qPrintable(q);
    EXPECT_TRUE(q.contains(QStringLiteral("48 V, 400 W"))) << qPrintable(q);
    EXPECT_TRUE(q.contains(QStringLiteral("DBU200-D: 0 or 250–3000 r/min; DBU400-D4: 0 or "
                                          "300–3000 r/min")))
        << qPrintable(q);
    EXPECT_TRUE(q.contains(QStringLiteral("Speed upper limit"))) << qPrintable(q);
    EXPECT_TRUE(q.contains(QStringLiteral("Last time on this bus it was set as DBU400-D4.")));
    EXPECT_EQ(VariantNeed::dependent(drives->session(1)->profile()).size(), 9);
}
