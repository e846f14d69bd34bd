// UnitStartGate, the one way a unit begins on the operator screen and with `eol run`: the retest
// rules first, before anything is sent (a passed serial refused, or held for a technician and let
// on when one allows it, its attempt numbered); then the positions made safe (a motor a killed
// station left turning that will not stop holds the unit back); then the unit begun, recorded
// before anything is written (a database that refuses the record gets no frame to a drive).
// A unit cancelled while it waits is dropped, and its late retest answer with it.
#include "model/station/UnitStartGate.h"

#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultStore.h"
#include "model/eol/ResultWriter.h"
#include "model/run/RunControl.h"
#include "tests/model/DriveSimFixture.h"
#include "tests/model/eol/RecipeTestSupport.h"
#include "tests/support/EolSampleUnit.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <memory>
#include <optional>

using namespace opentop;
using namespace opentop::test;

namespace {

using Kind = UnitStartGate::Outcome::Kind;

// The example DBU200 recipe at machine number 1 with short ramps and a short hold: a unit in
// about two seconds.
Recipe quickRecipe()
{
    Recipe recipe = exampleRecipe("recipe-dbu200.json");
    RecipePosition& p = recipe.positions[0];
    p.machineNumber = 1;
    for (RecipeSetting& s : p.settings)
        if (s.name == QLatin1String("spno2.accel") || s.name == QLatin1String("spno2.decel"))
            s.value = 0.5;
    for (RecipeStep& step : p.steps)
        if (step.type == RecipeStep::Type::Hold)
            step.duration = 1;
    return recipe;
}

class UnitStartGateTest : public DriveSimFixture
{
protected:
    void TearDown() override
    {
        run.reset(); // the unit's run before the bus it ran on
        DriveSimFixture::TearDown();
    }

    QString dbPath() const { return dir.filePath(QStringLiteral("results.db")); }

    // A verdict PASS for `serial` under `recipe`, as an earlier unit left it.
    void recordPass(const QString& serial, const Recipe& recipe)
    {
        QString error;
        const std::unique_ptr<ResultDatabase> db = ResultDatabase::open(dbPath(), &error);
        ASSERT_TRUE(db) << qPrintable(error);
        ResultStore store(*db);
        UnitRecord r = eolSampleUnit(serial, UnitStatus::Pass);
        r.recipeChecksum = RecipeFile::checksumOf(recipe);
        ASSERT_TRUE(store.beginUnit(r, &error)) << qPrintable(error);
        ASSERT_TRUE(store.finishUnit(r, &error)) << qPrintable(error);
    }

    void openDatabase()
    {
        const ResultWriter::Opened opened = writer.openAndWait(dbPath(), QString());
        ASSERT_TRUE(opened.ok) << qPrintable(opened.error);
    }

    UnitStartGate::Unit unitOf(const Recipe& recipe, const QString& serial)
    {
        UnitStartGate::Unit unit;
        unit.recipe = recipe;
        EolRun::Options& o = unit.options;
        o.serial = serial;
        o.station = QStringLiteral("line 1");
        o.operatorName = QStringLiteral("Lin");
        o.recipeChecksum = RecipeFile::checksumOf(recipe);
        for (const RecipePosition& p : recipe.positions)
            for (const RecipeUnitValue& u : p.unitValues)
                o.unitValues[p.machineNumber][u.name] = (u.min + u.max) / 2;
        o.timing.pollMs = 50;
        o.writer = &writer;
        o.traffic = &log;
        unit.client = [this] { return client.get(); };
        unit.retestPassed = [this](const RetestPolicy::Decision& d) { passed.append(d); };
        unit.made = [this](EolRun* made, ModbusClient*) { run.reset(made); };
        unit.finished = [this](const UnitRecord& r) { record = r; };
        return unit;
    }

    // Starts `unit` and waits for the gate's outcome (and, once begun, for the unit's record).
    UnitStartGate::Outcome pass(UnitStartGate& gate, const UnitStartGate::Unit& unit)
    {
        std::optional<UnitStartGate::Outcome> outcome;
        EXPECT_TRUE(gate.start(unit, [&](const UnitStartGate::Outcome& o) {
            EXPECT_FALSE(outcome) << "one outcome per unit";
            outcome = o;
        }));
        EXPECT_FALSE(outcome) << "never inside start()";
        EXPECT_TRUE(waitUntil([&] { return outcome.has_value(); }, 60000));
        if (outcome && outcome->kind == Kind::Begun) {
            EXPECT_TRUE(waitUntil([&] { return record.has_value(); }, 60000));
        }
        EXPECT_FALSE(gate.isPending());
        return outcome.value_or(UnitStartGate::Outcome{Kind::Cancelled, {}, {}});
    }

    int writesSent() const { return framesSent(6) + framesSent(16); }

    int reg(int slave, int address)
    {
        const QString text =
            bus->control(slave, {QStringLiteral("get"), QString::number(address)}).text;
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("= (\\d+) ")).match(text);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }

    // As a station killed mid-unit leaves a drive: turning, in communication priority.
    void leftRunning(int slave)
    {
        communicationPriority(slave);
        RunControl control(client.get(), ProfileRegistry::builtIn());
        RunControl::Command command;
        command.action = RunControl::Action::Start;
        const RunControl::Outcome o = await<RunControl::Outcome>(
            [&](auto done) { control.execute(session(slave), command, done); });
        ASSERT_TRUE(o.ok) << qPrintable(o.error);
        ASSERT_TRUE(waitUntil([&] { return reg(slave, 0x0109) > 0; })); // current speed
    }

    QTemporaryDir dir;
    ResultWriter writer;
    std::unique_ptr<EolRun> run;
    std::optional<UnitRecord> record;
    QVector<RetestPolicy::Decision> passed;
};

} // namespace

TEST_F(UnitStartGateTest, APassedSerialIsRefusedOrHeldBeforeAnythingIsSentAndATechnicianLetsItOn)
{
    startBus(QStringLiteral("dbu200@1"));
    Recipe recipe = quickRecipe();
    recordPass(QStringLiteral("SN-P"), recipe);
    openDatabase();
    UnitStartGate gate(ProfileRegistry::builtIn());
    const int framesBefore = framesSent();

    // A recipe that never tests a passed serial again.
    Recipe refusing = recipe;
    refusing.retest.passed = RecipeRetest::Passed::Refuse;
    UnitStartGate::Unit unit = unitOf(refusing, QStringLiteral("SN-P"));
    unit.technicianAllows = true; // no one may allow what the recipe refuses
    UnitStartGate::Outcome o = pass(gate, unit);
    EXPECT_EQ(o.kind, Kind::RetestRefused);
    EXPECT_EQ(o.serial, QStringLiteral("SN-P"));
    EXPECT_TRUE(o.message.contains(QStringLiteral("passed already"))) << qPrintable(o.message);

    // The default rules: a technician decides; without one the unit is held.
    o = pass(gate, unitOf(recipe, QStringLiteral("SN-P")));
    EXPECT_EQ(o.kind, Kind::NeedsTechnician);
    EXPECT_TRUE(o.message.contains(QStringLiteral("needs a technician"))) << qPrintable(o.message);
    EXPECT_EQ(framesSent(), framesBefore) << "the retest rules are checked before anything is sent";
    EXPECT_TRUE(passed.isEmpty());
    EXPECT_FALSE(run);
    EXPECT_FALSE(gate.isSafe()) << "no position was made safe for a unit held back";

    // A technician allows it: the override is said before the positions are made safe, and the
    // unit runs as the serial's second attempt.
    unit = unitOf(recipe, QStringLiteral("SN-P"));
    unit.technicianAllows = true;
    o = pass(gate, unit);
    ASSERT_EQ(o.kind, Kind::Begun) << qPrintable(o.message);
    EXPECT_TRUE(o.message.isEmpty());
    ASSERT_EQ(passed.size(), 1);
    EXPECT_EQ(passed[0].kind, RetestPolicy::Decision::Kind::NeedsTechnician);
    EXPECT_EQ(gate.decision().attempt, 2);
    EXPECT_TRUE(gate.isSafe());
    ASSERT_TRUE(run);
    ASSERT_TRUE(record);
    EXPECT_EQ(record->status, UnitStatus::Pass) << qPrintable(record->failureReason);
    EXPECT_EQ(record->attempt, 2);
}

TEST_F(UnitStartGateTest, AMotorLeftTurningThatWillNotStopHoldsTheUnitBack)
{
    startBus(QStringLiteral("dbu200@1"));
    leftRunning(1);
    control(1, {QStringLiteral("ignore-stop"), QStringLiteral("on")});
    openDatabase();
    UnitStartGate gate(ProfileRegistry::builtIn());
    StopConfirmer::Timing timing;
    timing.pollMs = 50;
    gate.setStopTiming(timing);
    int safetyChanges = 0;
    QObject::connect(&gate, &UnitStartGate::safetyChanged, [&] { ++safetyChanges; });

    const UnitStartGate::Outcome o = pass(gate, unitOf(quickRecipe(), QStringLiteral("SN-T")));
    EXPECT_EQ(o.kind, Kind::Unsafe);
    EXPECT_TRUE(o.message.contains(QStringLiteral("not safe"))) << qPrintable(o.message);
    EXPECT_TRUE(o.message.contains(QStringLiteral("NOT CONFIRMED STOPPED")))
        << qPrintable(o.message);
    EXPECT_EQ(passed.size(), 1) << "the retest rules let it on first";
    EXPECT_FALSE(run) << "no unit begun";
    EXPECT_FALSE(record);
    EXPECT_FALSE(gate.isSafe());
    EXPECT_FALSE(gate.isMakingSafe());
    EXPECT_EQ(safetyChanges, 2); // making safe began, and ended
    ASSERT_EQ(gate.safety().size(), 1);
    EXPECT_TRUE(gate.safety()[0].blocksUnits());
    EXPECT_GT(reg(1, 0x0109), 0) << "the simulated drive ignores the stop";

    // Nothing is remembered as safe: the next unit makes the positions safe again first.
    control(1, {QStringLiteral("ignore-stop"), QStringLiteral("off")});
    const UnitStartGate::Outcome next = pass(gate, unitOf(quickRecipe(), QStringLiteral("SN-T")));
    EXPECT_EQ(next.kind, Kind::Begun) << qPrintable(next.message);
    EXPECT_TRUE(gate.isSafe());
    EXPECT_EQ(safetyChanges, 4);
}

TEST_F(UnitStartGateTest, ABeginTheDatabaseRefusesSendsNothingToTheDrives)
{
    startBus(QStringLiteral("dbu200@1"));
    // The writer was never opened: the history cannot be read (the retest rules let the unit
    // on, saying so) and the unit's record cannot be begun.
    UnitStartGate gate(ProfileRegistry::builtIn());
    UnitStartGate::Unit unit = unitOf(quickRecipe(), QStringLiteral("SN-D"));
    int writesAtBegin = -1;
    unit.made = [&](EolRun* made, ModbusClient*) {
        run.reset(made);
        writesAtBegin = writesSent(); // the positions were made safe; the unit starts now
    };
    const UnitStartGate::Outcome o = pass(gate, unit);
    ASSERT_EQ(o.kind, Kind::Begun) << qPrintable(o.message);
    ASSERT_EQ(passed.size(), 1);
    EXPECT_TRUE(passed[0].reason.contains(QStringLiteral("not checked")))
        << qPrintable(passed[0].reason);
    EXPECT_TRUE(gate.isSafe());
    ASSERT_TRUE(record);
    EXPECT_EQ(record->status, UnitStatus::Error) << "the station's, not the unit's";
    EXPECT_TRUE(record->failureReason.contains(QStringLiteral("cannot record the unit")))
        << qPrintable(record->failureReason);
    EXPECT_TRUE(record->id.isEmpty());
    ASSERT_TRUE(run);
    EXPECT_FALSE(run->storeError().isEmpty());
    EXPECT_EQ(writesSent(), writesAtBegin) << "nothing is written for a unit not recorded";
}

TEST_F(UnitStartGateTest, AUnitCancelledWhileItWaitsIsDroppedWithItsRetestAnswer)
{
    startBus(QStringLiteral("dbu200@1"));
    openDatabase();
    UnitStartGate gate(ProfileRegistry::builtIn());
    const int framesBefore = framesSent();
    int outcomes = 0;
    UnitStartGate::Outcome last;
    ASSERT_TRUE(gate.start(unitOf(quickRecipe(), QStringLiteral("SN-C")),
                           [&](const UnitStartGate::Outcome& o) {
                               ++outcomes;
                               last = o;
                           }));
    EXPECT_TRUE(gate.isPending());
    EXPECT_EQ(gate.pendingSerial(), QStringLiteral("SN-C"));
    EXPECT_FALSE(gate.start(unitOf(quickRecipe(), QStringLiteral("SN-X")), {}))
        << "one unit at a time";
    ASSERT_TRUE(gate.cancel());
    EXPECT_FALSE(gate.isPending());
    EXPECT_EQ(outcomes, 1);
    EXPECT_EQ(last.kind, Kind::Cancelled);
    EXPECT_EQ(last.serial, QStringLiteral("SN-C"));
    EXPECT_EQ(last.message, QStringLiteral("cancelled before it started"));
    EXPECT_FALSE(gate.cancel());

    // The retest answer that comes after is dropped: no safe state, no unit, no second outcome.
    waitUntil([] { return false; }, 500);
    EXPECT_EQ(outcomes, 1);
    EXPECT_TRUE(passed.isEmpty());
    EXPECT_FALSE(run);
    EXPECT_EQ(framesSent(), framesBefore);
}
