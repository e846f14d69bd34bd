// One unit through the end-of-line run on the in-process simulator: PASS on good drives (one
// DBU, eight DBUs on one bus, a DC controller), FAIL with the right reason for each simulated
// defect, the motor stopped after every failure and after a cancel, and the record the store
// keeps equal to the one the run returns.
#include "model/eol/EolRun.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultWriter.h"
#include "model/profile/RoleEvaluator.h"
#include "tests/model/DriveSimFixture.h"
#include "tests/model/eol/RecipeTestSupport.h"

#include <QTemporaryDir>
#include <cctype>
#include <string>

using namespace opentop;
using namespace opentop::test;

namespace {

RecipeStep* stepOf(RecipePosition& position, RecipeStep::Type type)
{
    for (RecipeStep& s : position.steps)
        if (s.type == type)
            return &s;
    return nullptr;
}

// The example DBU200 recipe, with short ramps and a short hold so that a run takes about two
// seconds, at the given machine numbers.
Recipe quickDbuRecipe(const QVector<int>& machineNumbers)
{
    Recipe recipe = exampleRecipe("recipe-dbu200.json");
    const RecipePosition model = recipe.positions.value(0);
    recipe.positions.clear();
    for (int n : machineNumbers) {
        RecipePosition p = model;
        p.machineNumber = n;
        for (RecipeSetting& s : p.settings) {
            if (s.name == QLatin1String("spno2.accel") || s.name == QLatin1String("spno2.decel"))
                s.value = 0.5;
        }
        if (RecipeStep* hold = stepOf(p, RecipeStep::Type::Hold))
            hold->duration = 1;
        recipe.positions.append(p);
    }
    return recipe;
}

class EolRunTest : public DriveSimFixture
{
protected:
    UnitRecord run(const Recipe& recipe, ResultWriter* writer = nullptr,
                   std::function<void(EolRun&)> during = {})
    {
        EXPECT_EQ(textOf(problemsOf(recipe)), QString());
        EolRun::Options options;
        options.serial = QStringLiteral("SN-0001");
        options.station = QStringLiteral("line 1");
        options.operatorName = QStringLiteral("Lin");
        options.recipeChecksum = RecipeFile::checksumOf(recipe);
        for (const RecipePosition& p : recipe.positions)
            for (const RecipeUnitValue& u : p.unitValues)
                options.unitValues[p.machineNumber][u.name] = (u.min + u.max) / 2;
        options.timing.pollMs = 50;
        options.writer = writer;
        options.traffic = &log;
        EolRun eol(client.get(), ProfileRegistry::builtIn(), recipe, options);
        lastRun = &eol;
        if (during)
            during(eol);
        const UnitRecord record = await<UnitRecord>(
            [&eol](std::function<void(const UnitRecord&)> done) { eol.start(done); }, 60000);
        unconfirmed = eol.unconfirmedStops();
        lastRun = nullptr;
        return record;
    }

    // Whether the drive says its motor runs (read through the bus, as a master sees it).
    bool running(int slave)
    {
        DeviceSession* s = session(slave);
        const ParameterMeta* meta =
            RoleEvaluator::parameter(s->profile(), QStringLiteral("running"));
        const DeviceSession::Outcome r = await<DeviceSession::Outcome>(
            [&](DeviceSession::Done done) { s->read(meta->name, done); });
        EXPECT_TRUE(r.ok) << qPrintable(r.error);
        return RoleEvaluator::flag(
                   s->profile(), QStringLiteral("running"),
                   [&r](const QString&) { return std::optional<double>(r.value.raw); })
            .value_or(true);
    }

    QString readText(int slave, const QString& name)
    {
        DeviceSession* s = session(slave);
        const DeviceSession::Outcome r =
            await<DeviceSession::Outcome>([&](DeviceSession::Done done) { s->read(name, done); });
        EXPECT_TRUE(r.ok) << qPrintable(r.error);
        return r.value.text.isEmpty() ? QString::number(r.value.number) : r.value.text;
    }

    EolRun* lastRun = nullptr;
    QStringList unconfirmed;
};

} // namespace

TEST_F(EolRunTest, AGoodDriveIsWrittenVerifiedTestedAndPasses)
{
    startBus(QStringLiteral("dbu200@1"));
    const QString priorityBefore = readText(1, QStringLiteral("core.control_priority"));
    const UnitRecord r = run(quickDbuRecipe({1}));
    EXPECT_EQ(r.status, UnitStatus::Pass) << qPrintable(r.failureReason);
    EXPECT_TRUE(r.failureReason.isEmpty());
    ASSERT_EQ(r.drives.size(), 1);
    EXPECT_EQ(r.drives[0].variant, QStringLiteral("dbu200"));
    EXPECT_EQ(r.drives[0].firmware, QStringLiteral("1.5"));
    // Every setting and per-unit value, proven by reading it back.
    EXPECT_EQ(r.writtenValues.size(), 6);
    for (const WrittenValue& w : r.writtenValues)
        EXPECT_TRUE(w.verified) << qPrintable(w.label);
    EXPECT_EQ(readText(1, QStringLiteral("spno2.speed")), QStringLiteral("1500"));
    EXPECT_EQ(readText(1, QStringLiteral("spno3.speed")), QStringLiteral("1500"));
    // Time to speed, four hold statistics, time to stop, no alarm, the read.
    EXPECT_EQ(r.measurements.size(), 8);
    for (const Measurement& m : r.measurements)
        EXPECT_TRUE(m.pass) << qPrintable(m.quantity);
    EXPECT_FALSE(running(1));
    // The priority step's setting is given back as the drive held it.
    EXPECT_EQ(readText(1, QStringLiteral("core.control_priority")), priorityBefore);
}

// SPno1 decelerates as the SD knob is set, which cannot be read: the stop step allows the
// knob's maximum from the profile (30 s) plus the margin, not the unknown-deceleration default.
TEST_F(EolRunTest, StoppingSpno1AllowsTheKnobsMaximum)
{
    startBus(QStringLiteral("dbu200@1"));
    Recipe recipe = quickDbuRecipe({1});
    RecipePosition& p = recipe.positions[0];
    stepOf(p, RecipeStep::Type::Select)->spno = 1;
    QVector<RecipeStep> steps;
    for (const RecipeStep& s : p.steps)
        if (s.type != RecipeStep::Type::WaitSpeed && s.type != RecipeStep::Type::Hold)
            steps << s;
    p.steps = steps;
    const double margin = stepOf(p, RecipeStep::Type::Stop)->margin;
    const UnitRecord r = run(recipe);
    EXPECT_EQ(r.status, UnitStatus::Pass) << qPrintable(r.failureReason);
    bool found = false;
    for (const Measurement& m : r.measurements) {
        if (m.quantity != QLatin1String("time to stop"))
            continue;
        found = true;
        ASSERT_TRUE(m.upper);
        EXPECT_DOUBLE_EQ(*m.upper, 30.0 + margin);
    }
    EXPECT_TRUE(found);
    EXPECT_FALSE(running(1));
}

TEST_F(EolRunTest, ASecondRunWritesNothingThatIsAlreadyRight)
{
    startBus(QStringLiteral("dbu200@1"));
    const Recipe recipe = quickDbuRecipe({1});
    ASSERT_EQ(run(recipe).status, UnitStatus::Pass);
    const UnitRecord again = run(recipe);
    EXPECT_EQ(again.status, UnitStatus::Pass) << qPrintable(again.failureReason);
    for (const WrittenValue& w : again.writtenValues) {
        EXPECT_FALSE(w.written) << qPrintable(w.label);
        EXPECT_TRUE(w.verified) << qPrintable(w.label);
    }
}

TEST_F(EolRunTest, EightDrivesOnOneBusPassTogether)
{
    startBus(QStringLiteral("dbu200@1-8"));
    const UnitRecord r = run(quickDbuRecipe({1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(r.status, UnitStatus::Pass) << qPrintable(r.failureReason);
    EXPECT_EQ(r.drives.size(), 8);
    EXPECT_EQ(r.measurements.size(), 64);
    for (int slave = 1; slave <= 8; ++slave)
        EXPECT_FALSE(running(slave)) << slave;
}

TEST_F(EolRunTest, ADcControllerPasses)
{
    startBus(QStringLiteral("dcpid@7"));
    Recipe recipe = exampleRecipe("recipe-dcpid.json");
    RecipeStep* hold = stepOf(recipe.positions[0], RecipeStep::Type::Hold);
    ASSERT_TRUE(hold);
    hold->duration = 1;
    // Values the simulator does not start with, so that they must be written and stored.
    for (RecipeSetting& setting : recipe.positions[0].settings) {
        if (setting.name == QLatin1String("config.stall_time"))
            setting.value = 4.2;
        if (setting.name == QLatin1String("config.rated_current"))
            setting.value = 3.3;
    }
    ASSERT_NE(readText(7, QStringLiteral("config.stall_time")), QStringLiteral("4.2"));
    const UnitRecord r = run(recipe);
    EXPECT_EQ(r.status, UnitStatus::Pass) << qPrintable(r.failureReason);
    EXPECT_FALSE(r.measurements.isEmpty());
    EXPECT_FALSE(running(7));
    // The controller's settings are stored: they survive switching its power off and on.
    bus->device(7)->powerCycle(bus->nowMs());
    EXPECT_EQ(readText(7, QStringLiteral("config.stall_time")), QStringLiteral("4.2"));
    EXPECT_EQ(readText(7, QStringLiteral("config.rated_current")), QStringLiteral("3.3"));
}

struct DefectCase
{
    const char* defect;
    const char* reason; // what the failure must say
    bool wrote;         // whether settings were written before the failure
};

void PrintTo(const DefectCase& c, std::ostream* os)
{
    *os << c.defect;
}

class EolRunDefectTest : public EolRunTest, public ::testing::WithParamInterface<DefectCase>
{
};

TEST_P(EolRunDefectTest, FailsForTheRightReasonWithTheMotorStopped)
{
    const DefectCase c = GetParam();
    startBus(QStringLiteral("dbu200@1{%1}").arg(QString::fromLatin1(c.defect)));
    const UnitRecord r = run(quickDbuRecipe({1}));
    EXPECT_EQ(r.status, UnitStatus::Fail);
    EXPECT_TRUE(r.failureReason.contains(QString::fromUtf8(c.reason)))
        << qPrintable(r.failureReason);
    EXPECT_TRUE(r.failureReason.startsWith(QStringLiteral("position 1 (machine number 1)")))
        << qPrintable(r.failureReason);
    EXPECT_FALSE(r.traffic.isEmpty()) << "the traffic around the failure is recorded";
    EXPECT_EQ(!r.writtenValues.isEmpty(), c.wrote);
    EXPECT_TRUE(unconfirmed.isEmpty()) << qPrintable(unconfirmed.join(QLatin1Char('\n')));
    EXPECT_FALSE(running(1));
}

INSTANTIATE_TEST_SUITE_P(
    Defects, EolRunDefectTest,
    ::testing::Values(DefectCase{"firmware=1.4", "firmware 1.4, the recipe allows 1.5", false},
                      DefectCase{"nostick=spno2.speed", "SPno2", true},
                      DefectCase{"max_speed=800", "did not reach 1500 r/min", true},
                      DefectCase{"load=+60", "allowed at most 80 %", true},
                      DefectCase{"alarm=overload@700ms", "raised an alarm while running: AL007",
                                 true},
                      // A stalled motor trips the overload alarm (3 s) before the wait ends.
                      DefectCase{"stall", "AL007", true}),
    // Named by the defect ("max_speed_800"), not by the bytes of the case.
    [](const ::testing::TestParamInfo<DefectCase>& param) {
        std::string name = param.param.defect;
        for (char& c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c)))
                c = '_';
        }
        return name;
    });

TEST_F(EolRunTest, AMissingDriveIsAStationErrorWithoutSendingAnythingElse)
{
    startBus(QStringLiteral("dbu200@1"));
    const UnitRecord r = run(quickDbuRecipe({1, 2}));
    EXPECT_EQ(r.status, UnitStatus::Error); // the fixture's, not the unit's: no verdict
    EXPECT_TRUE(r.failureReason.contains(QStringLiteral("no drive answers at machine number 2")))
        << qPrintable(r.failureReason);
    EXPECT_FALSE(running(1));
}

TEST_F(EolRunTest, CancelWhileTheMotorRunsStopsItAndIsNeverAPass)
{
    startBus(QStringLiteral("dbu200@1"));
    Recipe recipe = quickDbuRecipe({1});
    stepOf(recipe.positions[0], RecipeStep::Type::Hold)->duration = 30;
    bool sawRunning = false;
    const UnitRecord r = run(recipe, nullptr, [&](EolRun& eol) {
        QObject::connect(&eol, &EolRun::measured, &eol, [&eol, &sawRunning](const Measurement& m) {
            // The speed was reached: the motor runs now, in the hold.
            if (m.quantity == QLatin1String("time to reach speed")) {
                sawRunning = true;
                QTimer::singleShot(300, &eol, [&eol] { eol.cancel(); });
            }
        });
    });
    EXPECT_TRUE(sawRunning);
    EXPECT_EQ(r.status, UnitStatus::Aborted);
    EXPECT_TRUE(r.failureReason.contains(QStringLiteral("cancelled")))
        << qPrintable(r.failureReason);
    EXPECT_TRUE(unconfirmed.isEmpty());
    EXPECT_FALSE(running(1));
}

TEST_F(EolRunTest, TheStoredRecordIsTheOneTheRunReturns)
{
    startBus(QStringLiteral("dbu200@1{load=+60}"));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("results.sqlite"));
    ResultWriter writer;
    const ResultWriter::Opened opened = writer.openAndWait(path, QStringLiteral("line 1"));
    ASSERT_TRUE(opened.ok) << qPrintable(opened.error);
    const UnitRecord r = run(quickDbuRecipe({1}), &writer);
    ASSERT_EQ(r.status, UnitStatus::Fail);
    ASSERT_FALSE(r.id.isEmpty());
    EXPECT_EQ(writer.pending(), 0); // the run ends once its record is stored
    QString error;
    const std::unique_ptr<ResultDatabase> db = ResultDatabase::open(path, &error);
    ASSERT_TRUE(db) << qPrintable(error);
    ResultQueries queries(*db);
    const std::optional<UnitRecord> stored = queries.load(r.id, &error);
    ASSERT_TRUE(stored) << qPrintable(error);
    EXPECT_EQ(*stored, r);
}

TEST_F(EolRunTest, AMotorAlreadyRunningIsNeitherWrittenNorTouched)
{
    startBus(QStringLiteral("dbu200@1"));
    communicationPriority(1);
    DeviceSession::WriteOptions explicitly;
    explicitly.explicitCommand = true;
    const DeviceSession::Outcome started = await<DeviceSession::Outcome>([&](auto done) {
        session(1)->write(QStringLiteral("run.start"), QStringLiteral("1"), explicitly, done);
    });
    ASSERT_TRUE(started.ok) << qPrintable(started.error);
    ASSERT_TRUE(waitUntil([&] { return running(1); }));
    const int writesBefore = framesSent(6) + framesSent(16);
    const UnitRecord r = run(quickDbuRecipe({1}));
    EXPECT_EQ(r.status, UnitStatus::Error);
    EXPECT_TRUE(r.failureReason.contains(QStringLiteral("already running")))
        << qPrintable(r.failureReason);
    EXPECT_TRUE(r.writtenValues.isEmpty());
    EXPECT_EQ(framesSent(6) + framesSent(16), writesBefore) << "nothing written, nothing stopped";
    EXPECT_EQ(unconfirmed.size(), 1) << "named as a motor not confirmed stopped";
    EXPECT_TRUE(running(1));
}
