// Issue 25 item 2: before a station's first unit, the recipe's positions are made safe. A motor
// a killed station left turning in communication priority is sent its own stop (never a
// broadcast), confirmed stopped and given back to its inputs; a position with no unit yet is
// fine; one that does not stop is reported and keeps communication priority.
#include "model/eol/StationSafeState.h"
#include "model/run/RunControl.h"
#include "model/station/EolStation.h"
#include "tests/model/DriveSimFixture.h"
#include "tests/model/eol/RecipeTestSupport.h"

#include <QRegularExpression>

using namespace opentop;
using namespace opentop::test;

namespace {

class StationSafeStateTest : public DriveSimFixture
{
protected:
    int reg(int slave, int address)
    {
        const QString text =
            bus->control(slave, {QStringLiteral("get"), QString::number(address)}).text;
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("= (\\d+) ")).match(text);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }
    // As a station killed 3 s into a unit leaves it: turning, in communication priority.
    void leftRunning(int slave)
    {
        communicationPriority(slave);
        RunControl control(client.get(), ProfileRegistry::builtIn());
        RunControl::Command command;
        command.action = RunControl::Action::Start;
        const RunControl::Outcome o = await<RunControl::Outcome>(
            [&](auto done) { control.execute(session(slave), command, done); });
        ASSERT_TRUE(o.ok) << qPrintable(o.error);
        ASSERT_TRUE(waitUntil([&] { return reg(slave, 0x0109) > 0; }));
    }
    Recipe recipeAt(const QVector<int>& machineNumbers)
    {
        Recipe recipe = exampleRecipe("recipe-dbu200.json");
        const RecipePosition model = recipe.positions.value(0);
        recipe.positions.clear();
        for (int n : machineNumbers) {
            RecipePosition p = model;
            p.machineNumber = n;
            recipe.positions.append(p);
        }
        return recipe;
    }
    QVector<PositionSafety> makeSafe(const Recipe& recipe)
    {
        StationSafeState safe(client.get(), ProfileRegistry::builtIn(), recipe);
        StopConfirmer::Timing timing;
        timing.pollMs = 50;
        safe.setStopTiming(timing);
        return await<QVector<PositionSafety>>([&](auto done) { safe.run(done); }, 60000);
    }
    int broadcasts() const
    {
        int n = 0;
        for (const TrafficEntry& e : log.entries())
            n += e.direction == TrafficEntry::Direction::Tx && e.slave == 0 ? 1 : 0;
        return n;
    }
};

} // namespace

TEST_F(StationSafeStateTest, AMotorLeftRunningIsStoppedConfirmedAndGivenBackToItsInputs)
{
    startBus(QStringLiteral("dbu200@1,dbu200@2,dbu200@9"));
    leftRunning(1);
    communicationPriority(2); // stopped, but left in communication priority
    const QVector<PositionSafety> found = makeSafe(recipeAt({1, 2, 5}));
    ASSERT_EQ(found.size(), 3);

    EXPECT_TRUE(found[0].answered);
    EXPECT_EQ(found[0].running, true);
    EXPECT_TRUE(found[0].stopSent);
    EXPECT_TRUE(found[0].stopConfirmed);
    EXPECT_TRUE(found[0].priorityGivenBack);
    EXPECT_TRUE(found[0].safe()) << qPrintable(found[0].summary());
    EXPECT_TRUE(found[0].summary().contains(QStringLiteral("was RUNNING")))
        << qPrintable(found[0].summary());
    EXPECT_TRUE(found[0].summary().contains(QStringLiteral("stopped by the station")))
        << qPrintable(found[0].summary());
    EXPECT_EQ(reg(1, 0x0109), 0) << "turning no more";
    EXPECT_EQ(reg(1, 0x100D), 1) << "its inputs control it again";

    EXPECT_EQ(found[1].running, false);
    EXPECT_FALSE(found[1].stopSent) << "a stopped drive is sent no stop";
    EXPECT_TRUE(found[1].priorityGivenBack);
    EXPECT_EQ(reg(2, 0x100D), 1);

    // No unit in the fixture at position 5: nothing to make safe, not a problem.
    EXPECT_FALSE(found[2].answered);
    // Drive 9 is on the bus but not the station's: nothing reached it, no broadcast was sent.
    EXPECT_EQ(broadcasts(), 0);
    for (const TrafficEntry& e : log.entries())
        EXPECT_NE(e.slave, 9) << "a drive that is not the station's was addressed";
}

TEST_F(StationSafeStateTest, AMotorThatDoesNotStopIsReportedAndKeptInCommunicationPriority)
{
    startBus(QStringLiteral("dbu200@1"));
    leftRunning(1);
    control(1, {QStringLiteral("ignore-stop"), QStringLiteral("on")});
    const QVector<PositionSafety> found = makeSafe(recipeAt({1}));
    ASSERT_EQ(found.size(), 1);
    EXPECT_TRUE(found[0].stopSent);
    EXPECT_FALSE(found[0].stopConfirmed);
    EXPECT_FALSE(found[0].safe());
    EXPECT_TRUE(found[0].summary().contains(QStringLiteral("NOT CONFIRMED STOPPED")))
        << qPrintable(found[0].summary());
    EXPECT_EQ(reg(1, 0x100D), 2) << "its inputs are not handed a motor the station cannot stop";
}

// The one rule of the operator screen and `eol run` for whether a unit may start after the
// positions were made safe.
TEST(PositionSafetyTest, OnlyAMotorLeftTurningOrLeftInBusControlBlocksAUnit)
{
    PositionSafety turning;
    turning.machineNumber = 1;
    turning.answered = true;
    turning.running = true;
    turning.busPriority = true;
    turning.problem = QStringLiteral("did not stop");
    EXPECT_TRUE(turning.blocksUnits());

    PositionSafety heldInBus = turning;
    heldInBus.machineNumber = 2;
    heldInBus.stopConfirmed = true;
    heldInBus.problem = QStringLiteral("control could not be given back to its inputs");
    EXPECT_TRUE(heldInBus.blocksUnits());

    PositionSafety absent;
    absent.machineNumber = 3; // no unit in the fixture yet
    EXPECT_FALSE(absent.blocksUnits());

    PositionSafety machine = turning;
    machine.machineNumber = 4;
    machine.busPriority = false; // turning from its own inputs: the machine's, reported only
    EXPECT_FALSE(machine.blocksUnits());

    PositionSafety stopped = turning;
    stopped.machineNumber = 5;
    stopped.stopConfirmed = true;
    stopped.problem.clear();
    EXPECT_FALSE(stopped.blocksUnits());

    const QString text =
        PositionSafety::blockingText({turning, heldInBus, absent, machine, stopped});
    EXPECT_EQ(text, turning.summary() + QStringLiteral("; ") + heldInBus.summary());
    EXPECT_TRUE(PositionSafety::blockingText({absent, machine, stopped}).isEmpty());
}
