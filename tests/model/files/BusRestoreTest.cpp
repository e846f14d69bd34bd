// BusRestore, the one restore workflow of several drives: every drive checked before any is
// written (one refusal writes nothing anywhere), each restored in turn, and after a cancel the
// drives not reached are reported as not attempted and do not decide the outcome.
#include "model/files/BusRestore.h"
#include "tests/model/files/BackupTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr quint16 kSpno2Speed = 0xCA03; // DBU running data SPno2 speed (r/min)

class BusRestoreTest : public SimBusFixture
{
protected:
    BusRestore::Sessions sessions()
    {
        return [this](int slave) {
            return slave == 1 || slave == 150 || slave == 7 ? session(slave) : nullptr;
        };
    }

    BackupDevice backupOf(int slave)
    {
        const BackupReader::Result r = backup(slave);
        EXPECT_TRUE(r.ok) << qPrintable(r.failures.join(QLatin1Char('\n')));
        return r.device;
    }

    QVector<RestorePlan> run(BusRestore& restore, const QVector<BusRestore::Job>& jobs,
                             bool dryRun = false)
    {
        return waitFor<QVector<RestorePlan>>([&](auto done) { restore.start(jobs, dryRun, done); });
    }
};

} // namespace

TEST_F(BusRestoreTest, TwoDrivesAreBroughtBackAndEachPlanSaysSo)
{
    const BackupDevice first = backupOf(1);
    const BackupDevice second = backupOf(150);
    const int speed1 = held(1, kSpno2Speed);
    const int speed150 = held(150, kSpno2Speed);
    set(1, kSpno2Speed, 1700);
    set(150, kSpno2Speed, 1800);

    BusRestore restore(sessions());
    const QVector<BusRestore::Job> jobs{{1, first}, {150, second}};
    EXPECT_TRUE(restore.check(jobs).isEmpty());
    // A preview writes nothing.
    QVector<RestorePlan> plans = run(restore, jobs, true);
    ASSERT_EQ(plans.size(), 2);
    EXPECT_EQ(plans[0].outcome, RestorePlan::Outcome::Planned);
    EXPECT_EQ(held(1, kSpno2Speed), 1700);

    QVector<int> started;
    QObject::connect(&restore, &BusRestore::driveStarted,
                     [&started](int slave, int, int) { started << slave; });
    plans = run(restore, jobs);
    ASSERT_EQ(plans.size(), 2);
    EXPECT_EQ(started, (QVector<int>{1, 150}));
    for (const RestorePlan& p : plans) {
        EXPECT_EQ(p.outcome, RestorePlan::Outcome::Done) << qPrintable(p.reason);
        EXPECT_TRUE(p.attempted);
    }
    EXPECT_EQ(plans[0].slave, 1);
    EXPECT_EQ(plans[1].slave, 150);
    EXPECT_EQ(held(1, kSpno2Speed), speed1);
    EXPECT_EQ(held(150, kSpno2Speed), speed150);
    EXPECT_EQ(BusRestore::worst(plans), RestorePlan::Outcome::Done);
}

TEST_F(BusRestoreTest, OneRefusedDriveMeansNothingIsWrittenAnywhere)
{
    const BackupDevice dbu = backupOf(1);
    set(1, kSpno2Speed, 1700);
    BusRestore restore(sessions());
    // The DBU's settings onto the DC controller, and onto a machine number nobody answers.
    const QVector<RestorePlan> refusals = restore.check({{1, dbu}, {7, dbu}, {33, dbu}});
    ASSERT_EQ(refusals.size(), 2);
    EXPECT_EQ(refusals[0].slave, 7);
    EXPECT_TRUE(refusals[0].refused());
    EXPECT_FALSE(refusals[0].reason.isEmpty());
    EXPECT_EQ(refusals[1].slave, 33);
    EXPECT_TRUE(refusals[1].reason.contains(QStringLiteral("33")))
        << qPrintable(refusals[1].reason);
    EXPECT_EQ(held(1, kSpno2Speed), 1700); // checking sends no write
}

TEST_F(BusRestoreTest, ACancelLeavesTheDrivesNotReachedNotAttemptedAndOutOfTheOutcome)
{
    const BackupDevice first = backupOf(1);
    const BackupDevice second = backupOf(150);
    set(1, kSpno2Speed, 1700);
    set(150, kSpno2Speed, 1800);
    BusRestore restore(sessions());
    QObject::connect(&restore, &BusRestore::driveStarted, &restore,
                     [&restore](int, int index, int) {
                         if (index == 0)
                             restore.cancel();
                     });
    const QVector<RestorePlan> plans = run(restore, {{1, first}, {150, second}});
    ASSERT_EQ(plans.size(), 2);
    EXPECT_TRUE(plans[0].attempted);
    EXPECT_FALSE(plans[1].attempted);
    EXPECT_EQ(plans[1].outcome, RestorePlan::Outcome::Interrupted);
    EXPECT_EQ(plans[1].reason, QStringLiteral("not attempted"));
    EXPECT_EQ(held(150, kSpno2Speed), 1800); // not reached, not written
    // The first drive's one write finishes with its read-back; the run is a cancelled one, never
    // a success, though every drive attempted was done.
    EXPECT_EQ(plans[0].outcome, RestorePlan::Outcome::Done);
    EXPECT_EQ(BusRestore::worst(plans), RestorePlan::Outcome::Interrupted);
    // After a lost bus, the failure says why; the drives left out do not turn it into a cancel.
    QVector<RestorePlan> lost = plans;
    lost[0].outcome = RestorePlan::Outcome::Communication;
    EXPECT_EQ(BusRestore::worst(lost), RestorePlan::Outcome::Communication);
}
