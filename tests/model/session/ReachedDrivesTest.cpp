// A write to a communication group's parent reaches its children too (they execute it without
// replying): each child validates the value by its own profile and variant before anything is
// sent, and each is read back afterwards; the write is verified only when every drive holds it.
// Against the in-process simulator, whose children execute the parent's frames.
#include "model/session/ReachedDrives.h"
#include "model/bus/BusGroupTracker.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "model/session/GroupReach.h"
#include "tests/model/DriveSimFixture.h"

#include <QRegularExpression>

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr quint16 kSpno5Speed = 0xCA09;
const QString kSpeed = QStringLiteral("spno5.speed");

// The children of drive 1, as a test says they are.
class FixedReach : public GroupReach
{
public:
    QVector<DeviceSession*> children;
    QVector<DeviceSession*> reachedBy(int slave) const override
    {
        return slave == 1 ? children : QVector<DeviceSession*>();
    }
};

class ReachedDrivesTest : public DriveSimFixture
{
protected:
    // Drive 1 (DBU200) is the parent of 2 (DBU200) and 150 (DBU400) in the simulator too.
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1,dbu200@2,dbu400@150"));
        for (int child : {2, 150})
            control(child, {QStringLiteral("set"), QStringLiteral("0x00F5"), QStringLiteral("1")});
        reach.children = {session(2), session(150)};
        session(1)->setGroupReach(&reach);
    }

    DeviceSession::Outcome write(const QString& text, const QString& name = kSpeed)
    {
        return await<DeviceSession::Outcome>(
            [&](auto done) { session(1)->write(name, text, {}, done); });
    }

    int simRegister(int slave, quint16 address)
    {
        const QString text =
            bus->control(slave, {QStringLiteral("get"), QString::number(address)}).text;
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("= (\\d+) ")).match(text);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }

    FixedReach reach;
};

} // namespace

TEST_F(ReachedDrivesTest, AChildsOwnRangeRefusesTheWriteAndNothingIsSent)
{
    const int before1 = simRegister(1, kSpno5Speed);
    const int before150 = simRegister(150, kSpno5Speed);
    const int writes = framesSent(6) + framesSent(16);
    // 280 r/min is allowed on a DBU200 (0 or 250–3000), not on a DBU400 (0 or 300–3000).
    const DeviceSession::Outcome refused = write(QStringLiteral("280"));
    EXPECT_FALSE(refused.ok);
    EXPECT_FALSE(refused.sent);
    EXPECT_TRUE(refused.error.contains(QStringLiteral("machine number 150 (DBU400-D4)")))
        << qPrintable(refused.error);
    EXPECT_TRUE(refused.error.contains(QStringLiteral("0 or 300–3000 r/min")))
        << qPrintable(refused.error);
    EXPECT_FALSE(refused.error.contains(QStringLiteral("machine number 2 ")))
        << qPrintable(refused.error); // drive 2 (a DBU200) allows it
    EXPECT_EQ(framesSent(6) + framesSent(16), writes);
    EXPECT_EQ(simRegister(1, kSpno5Speed), before1);
    EXPECT_EQ(simRegister(150, kSpno5Speed), before150);
    // The same refusal before any question is asked, from what is known.
    EXPECT_FALSE(session(1)
                     ->reachedProblem(kSpeed, ValueCodec::rawToRegisters(
                                                  *session(1)->profile().parameter(kSpeed), 280))
                     .isEmpty());

    // 300 r/min suits both: sent, and every drive reached is read back and holds it.
    const DeviceSession::Outcome written = write(QStringLiteral("300"));
    EXPECT_TRUE(written.ok) << qPrintable(written.error);
    EXPECT_TRUE(written.verified);
    ASSERT_EQ(written.reached.size(), 2);
    EXPECT_EQ(written.reached.at(0).slave, 2);
    EXPECT_TRUE(written.reached.at(0).verified);
    EXPECT_EQ(written.reached.at(1).slave, 150);
    EXPECT_TRUE(written.reached.at(1).verified);
    EXPECT_EQ(written.reached.at(1).held, QStringLiteral("300 r/min"));
    EXPECT_EQ(simRegister(150, kSpno5Speed), 300);
    EXPECT_EQ(session(150)->cachedValue(kSpeed).number, 300); // read from it, not assumed
}

TEST_F(ReachedDrivesTest, AChildOfUnknownVariantIsHeldToTheStrictestRangeAndSaysSo)
{
    session(2)->setVariant(QString()); // a DBU that does not report its variant
    reach.children = {session(2)};
    const DeviceSession::Outcome refused = write(QStringLiteral("280"));
    EXPECT_FALSE(refused.sent);
    EXPECT_TRUE(refused.error.contains(QStringLiteral("machine number 2 (DBU, variant not known)")))
        << qPrintable(refused.error);
    EXPECT_TRUE(refused.error.contains(QStringLiteral("the variant is not known")))
        << qPrintable(refused.error);
    // Named by hand, it is held to its own range.
    session(2)->setVariant(QStringLiteral("dbu200"));
    const DeviceSession::Outcome written = write(QStringLiteral("280"));
    EXPECT_TRUE(written.ok) << qPrintable(written.error);
    EXPECT_TRUE(written.verified);
    EXPECT_EQ(simRegister(2, kSpno5Speed), 280);
}

TEST_F(ReachedDrivesTest, AChildHoldingAnotherValueIsAVerificationFailureNamingIt)
{
    // The child acknowledges nothing and keeps its value: a drive that did not take it.
    control(150, {QStringLiteral("defect"), QStringLiteral("nostick=spno5.speed")});
    const int before = simRegister(150, kSpno5Speed);
    ASSERT_NE(before, 1500);
    const DeviceSession::Outcome o = write(QStringLiteral("1500"));
    EXPECT_TRUE(o.sent);
    EXPECT_FALSE(o.ok);
    EXPECT_TRUE(o.mismatch);
    EXPECT_FALSE(o.verified);
    EXPECT_EQ(simRegister(1, kSpno5Speed), 1500); // the parent holds it
    EXPECT_TRUE(o.error.contains(
        QStringLiteral("machine number 150 holds %1 r/min, not 1500 r/min").arg(before)))
        << qPrintable(o.error);
    ASSERT_EQ(o.reached.size(), 2);
    EXPECT_TRUE(o.reached.at(0).verified);
    EXPECT_TRUE(o.reached.at(1).mismatch);
}

TEST_F(ReachedDrivesTest, AChildThatCannotBeReadBackLeavesTheWriteNotVerified)
{
    // Drive 99 is named a child but does not answer: the write holds on 1 and 2, and says it
    // could not be verified on 99.
    reach.children = {session(2), session(99)};
    const DeviceSession::Outcome o = write(QStringLiteral("1600"));
    EXPECT_TRUE(o.ok) << qPrintable(o.error);
    EXPECT_FALSE(o.verified);
    EXPECT_FALSE(o.mismatch);
    EXPECT_TRUE(o.notVerified.contains(QStringLiteral("machine number 99: not verified")))
        << qPrintable(o.notVerified);
    EXPECT_EQ(simRegister(2, kSpno5Speed), 1600);
}

TEST_F(ReachedDrivesTest, APageEditIsRefusedAtTheFieldAndThroughTheTrackerToo)
{
    // The program's own provider: the tracker knows the groups from the drives.
    session(1)->setGroupReach(nullptr);
    auto drives = identifiedDrives({1, 2, 150});
    auto* tracker = new BusGroupTracker(drives.get());
    ASSERT_TRUE(waitUntil([&] { return tracker->groups().childrenOf(1).size() == 2; }));
    DeviceParameters* parent = drives->parameters(1);
    const QString refused = parent->setPending(kSpeed, QStringLiteral("280"));
    EXPECT_TRUE(refused.contains(QStringLiteral("machine number 150"))) << qPrintable(refused);
    EXPECT_EQ(parent->entry(kSpeed)->state, DeviceParameters::State::Invalid);
    // A page with it is not written at all.
    const int writes = framesSent(6);
    bool finished = false;
    parent->write({}, [&](int) { finished = true; });
    ASSERT_TRUE(waitUntil([&] { return finished; }));
    EXPECT_EQ(framesSent(6), writes);

    // A child that diverges: the field fails and says which child holds what.
    control(150, {QStringLiteral("defect"), QStringLiteral("nostick=spno5.speed")});
    ASSERT_TRUE(parent->setPending(kSpeed, QStringLiteral("1700")).isEmpty());
    int failed = -1;
    parent->write({}, [&](int f) { failed = f; });
    ASSERT_TRUE(waitUntil([&] { return failed >= 0; }));
    EXPECT_EQ(failed, 1);
    EXPECT_EQ(parent->entry(kSpeed)->state, DeviceParameters::State::Failed);
    bool problem = false;
    const QString status = parent->writeResultText({kSpeed}, failed, &problem);
    EXPECT_TRUE(problem);
    EXPECT_TRUE(status.contains(QStringLiteral("machine number 150 holds"))) << qPrintable(status);
    EXPECT_FALSE(status.contains(QStringLiteral("verified"))) << qPrintable(status);
}
