// RecipeChecker: one test per kind of problem. Each starts from an example recipe that passes
// and breaks one thing, and asserts that exactly that is reported, with the entry's path and a
// message naming the position, the setting's label and the allowed values.
#include "tests/model/eol/RecipeTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class RecipeCheckerTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        dbu = exampleRecipe("recipe-dbu200.json");
        dc = exampleRecipe("recipe-dcpid.json");
        ASSERT_TRUE(problemsOf(dbu).isEmpty()) << qPrintable(textOf(problemsOf(dbu)));
        ASSERT_TRUE(problemsOf(dc).isEmpty()) << qPrintable(textOf(problemsOf(dc)));
    }

    // The one problem `recipe` has; fails unless there is exactly one.
    static RecipeProblem only(const Recipe& recipe)
    {
        const QVector<RecipeProblem> problems = problemsOf(recipe);
        EXPECT_EQ(problems.size(), 1) << qPrintable(textOf(problems));
        return problems.value(0);
    }

    static RecipeSetting* setting(Recipe& recipe, const char* name)
    {
        for (RecipeSetting& s : recipe.positions[0].settings) {
            if (s.name == QLatin1String(name))
                return &s;
        }
        ADD_FAILURE() << "no setting " << name;
        static RecipeSetting none;
        return &none;
    }

    static RecipeStep& step(Recipe& recipe, RecipeStep::Type type)
    {
        for (RecipeStep& s : recipe.positions[0].steps) {
            if (s.type == type)
                return s;
        }
        ADD_FAILURE() << "no such step";
        static RecipeStep none;
        return none;
    }

    Recipe dbu;
    Recipe dc;
};

TEST_F(RecipeCheckerTest, ValueOutsideTheAllowedRangeNamesPositionLabelAndRange)
{
    dbu.positions[0].machineNumber = 5;
    setting(dbu, "spno2.accel")->value = 99;
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].settings[1].value"));
    EXPECT_EQ(p.message, QStringLiteral("position 1 (machine number 5): setting 'SPno2 "
                                        "acceleration time': 99.0 s is not allowed; allowed: "
                                        "0.5–30.0 s"));
}

TEST_F(RecipeCheckerTest, ValueMustSuitEveryAllowedVariant)
{
    setting(dbu, "spno2.speed")->value = 260; // a DBU200 allows 250–3000, a DBU400 300–3000
    EXPECT_TRUE(problemsOf(dbu).isEmpty()) << "a DBU200 alone allows it";
    dbu.positions[0].variants << QStringLiteral("dbu400");
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].settings[0].value"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("'SPno2 speed': 260 r/min is not allowed")))
        << qPrintable(p.message);
    EXPECT_TRUE(p.message.contains(QStringLiteral("300–3000 r/min"))) << qPrintable(p.message);
    EXPECT_TRUE(p.message.contains(QStringLiteral("DBU400-D4"))) << qPrintable(p.message);
    // no variants named: every variant of the family
    dbu.positions[0].variants.clear();
    EXPECT_EQ(only(dbu).path, QStringLiteral("positions[0].settings[0].value"));
}

TEST_F(RecipeCheckerTest, EnumerationValuesAreCheckedByLabel)
{
    setting(dbu, "spno2.direction")->value = QStringLiteral("sideways");
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].settings[3].value"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("'SPno2 direction': \"sideways\" is not a valid "
                                                  "value; allowed: CW (0), CCW (1)")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, UnknownParameter)
{
    dbu.positions[0].settings << RecipeSetting{QStringLiteral("spno9.speed"), 100, {}};
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].settings[5].name"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("has no setting \"spno9.speed\"")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, ParameterThatIsNotAWritableSetting)
{
    dbu.positions[0].settings << RecipeSetting{QStringLiteral("status.load"), 10, {}};
    const RecipeProblem p = only(dbu);
    EXPECT_TRUE(p.message.contains(QStringLiteral("'Load rate' is not a setting a recipe can "
                                                  "write")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, CommunicationSettingsAreRefused)
{
    dbu.positions[0].settings << RecipeSetting{
        QStringLiteral("comm.rate"), QStringLiteral("9600"), {}};
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].settings[5].name"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("'Communication rate' decides how the drive "
                                                  "communicates")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, SettingGivenTwice)
{
    dbu.positions[0].settings << RecipeSetting{QStringLiteral("spno2.speed"), 1000, {}};
    EXPECT_TRUE(only(dbu).message.contains(QStringLiteral("'SPno2 speed' is given twice")));
}

TEST_F(RecipeCheckerTest, WrongUnitOnASetting)
{
    setting(dbu, "spno2.accel")->unit = QStringLiteral("ms");
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].settings[1].unit"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("unit \"ms\", but the drive's value is in "
                                                  "\"s\"")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, SettingWhoseAllowedValuesDependOnASettingTheRecipeLacks)
{
    dbu.positions[0].settings << RecipeSetting{
        QStringLiteral("io.x0"), QStringLiteral("CW/STOP"), {}};
    const RecipeProblem p = only(dbu);
    EXPECT_TRUE(p.message.contains(QStringLiteral("'Input X0 function': what it allows depends "
                                                  "on 'Control mode', which the recipe does not "
                                                  "set")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, ControllingSettingNeedsItsDependents)
{
    dbu.positions[0].settings << RecipeSetting{QStringLiteral("core.control_mode"), 1, {}};
    const QString text = textOf(problemsOf(dbu));
    EXPECT_TRUE(text.contains(QStringLiteral("'Control mode' decides what 'Input X0 function' "
                                             "allows")))
        << qPrintable(text);
    // with every dependent set to a value the mode allows, nothing is left
    for (const char* name : {"io.x0", "io.x1", "io.x2", "io.x3"})
        dbu.positions[0].settings << RecipeSetting{
            QString::fromLatin1(name), QStringLiteral("Not functioning"), {}};
    EXPECT_TRUE(problemsOf(dbu).isEmpty()) << qPrintable(textOf(problemsOf(dbu)));
    // and a dependent's value is checked in the recipe's own control mode
    dbu.positions[0].settings.last().value = QStringLiteral("RUN/STOP"); // a Mode1 function
    EXPECT_TRUE(only(dbu).message.contains(QStringLiteral("'Input X3 function'")));
}

TEST_F(RecipeCheckerTest, PerUnitRangeOutsideWhatTheDriveAllows)
{
    dbu.positions[0].unitValues[0].min = 100;
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].unitValues[0].min"));
    EXPECT_TRUE(p.message.startsWith(QStringLiteral("position 1 (machine number 1): per-unit "
                                                    "value 'SPno3 speed': range 100–1600 r/min "
                                                    "is outside what the drive allows")))
        << qPrintable(p.message);
    EXPECT_TRUE(p.message.contains(QStringLiteral("250–3000 r/min"))) << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, PerUnitRangeAcrossAGapInTheAllowedValues)
{
    dbu.positions[0].unitValues[0].min = 0; // 0 and 1600 are allowed, 1–249 are not
    const RecipeProblem p = only(dbu);
    EXPECT_TRUE(p.message.contains(QStringLiteral("range 0–1600 r/min includes values the drive "
                                                  "does not allow; allowed: 0 or 250–3000 r/min")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, PerUnitRangeUpsideDown)
{
    dbu.positions[0].unitValues[0].min = 1700;
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].unitValues[0].max"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("lowest value 1700 is above its highest value "
                                                  "1600")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, PerUnitValueThatIsAlsoASetting)
{
    dbu.positions[0].unitValues[0].name = QStringLiteral("spno2.speed");
    EXPECT_TRUE(only(dbu).message.contains(QStringLiteral("'SPno2 speed' is given twice")));
}

TEST_F(RecipeCheckerTest, LimitLowerAboveUpper)
{
    RecipeLimit& mean = step(dbu, RecipeStep::Type::Hold).limits[1];
    mean.lower = 1600;
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[4].limits[1].upper"));
    EXPECT_EQ(p.message, QStringLiteral("position 1 (machine number 1), step 5 (hold and measure): "
                                        "'Current speed': the lower limit 1600 r/min is above the "
                                        "upper limit 1525 r/min"));
}

TEST_F(RecipeCheckerTest, LimitUnitMustBeTheMeasuredValuesUnit)
{
    step(dbu, RecipeStep::Type::Hold).limits[3].unit = QStringLiteral("A"); // load is in %
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[4].limits[3].unit"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("'Load rate': the limit's unit is \"A\", but the "
                                                  "value is measured in \"%\"")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, StatisticMustBeKnown)
{
    step(dbu, RecipeStep::Type::Hold).limits[0].statistic = QStringLiteral("median");
    EXPECT_EQ(only(dbu).path, QStringLiteral("positions[0].steps[4].limits[0].statistic"));
}

TEST_F(RecipeCheckerTest, HoldTimeOfZero)
{
    step(dbu, RecipeStep::Type::Hold).duration = 0;
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[4].duration"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("the hold time 0 s is not sane")));
}

TEST_F(RecipeCheckerTest, WaitLongerThanTheSaneMaximum)
{
    step(dbu, RecipeStep::Type::WaitSpeed).timeout = 3600;
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[3].timeout"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("3600 s is not sane; give more than 0 s and at "
                                                  "most 600 s")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, NegativeStopMargin)
{
    step(dbu, RecipeStep::Type::Stop).margin = -1;
    EXPECT_EQ(only(dbu).path, QStringLiteral("positions[0].steps[5].margin"));
}

TEST_F(RecipeCheckerTest, MachineNumberTwice)
{
    Recipe eight = exampleRecipe("recipe-eight-dbu.json");
    eight.positions[5].machineNumber = 2;
    const RecipeProblem p = only(eight);
    EXPECT_EQ(p.path, QStringLiteral("positions[5].machineNumber"));
    EXPECT_EQ(p.message, QStringLiteral("position 6 (machine number 2): machine number 2 is "
                                        "already position 2; every drive of a unit needs its "
                                        "own machine number"));
}

TEST_F(RecipeCheckerTest, MachineNumberOutOfRange)
{
    dbu.positions[0].machineNumber = 0;
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].machineNumber"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("takes machine numbers 1–247")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, UnknownFamily)
{
    dbu.positions[0].family = QStringLiteral("vfd");
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].family"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("unknown family \"vfd\"; known: dbu, dcpid")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, UnknownVariant)
{
    dbu.positions[0].variants = {QStringLiteral("dbu800")};
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].variants[0]"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("no variant \"dbu800\"; known: dbu200, dbu400")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, MalformedFirmwareVersion)
{
    dbu.positions[0].firmware = {QStringLiteral("1.5"), QStringLiteral("v1")};
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].firmware[1]"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("\"v1\" is not a version")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, StepsTheFamilyCannotDo)
{
    RecipeStep select;
    select.type = RecipeStep::Type::Select;
    select.spno = 2;
    dc.positions[0].steps.prepend(select);
    const RecipeProblem p = only(dc);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[0].type"));
    EXPECT_TRUE(p.message.startsWith(QStringLiteral("position 1 (machine number 7), step 1 (select "
                                                    "running data): a ")));
    EXPECT_TRUE(p.message.endsWith(QStringLiteral("DC motor PID controller cannot do this step")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, RunningDataNumberMustExist)
{
    step(dbu, RecipeStep::Type::Select).spno = 9;
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[1].spno"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("running data 9"))) << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, StartWithoutCommunicationPriority)
{
    dbu.positions[0].steps.removeFirst(); // the priority step
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[1].type"));
    EXPECT_TRUE(p.message.startsWith(QStringLiteral("position 1 (machine number 1), step 2 "
                                                    "(start): the drive takes motion commands "
                                                    "only with communication priority")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, StepsLeaveTheMotorRunning)
{
    dbu.positions[0].steps.remove(5); // the stop step
    const RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("leave the motor running")));
}

TEST_F(RecipeCheckerTest, WaitAndHoldWhileTheMotorIsStopped)
{
    dbu.positions[0].steps.remove(2); // the start step
    const QVector<RecipeProblem> problems = problemsOf(dbu);
    ASSERT_EQ(problems.size(), 2) << qPrintable(textOf(problems));
    EXPECT_EQ(problems.at(0).path, QStringLiteral("positions[0].steps[2].type"));
    EXPECT_TRUE(problems.at(0).message.contains(QStringLiteral("the motor is not running here")));
    EXPECT_EQ(problems.at(1).path, QStringLiteral("positions[0].steps[3].type"));
}

TEST_F(RecipeCheckerTest, StopWithoutADecelerationWhereTheDriveHasNone)
{
    step(dc, RecipeStep::Type::Stop).deceleration.reset();
    const RecipeProblem p = only(dc);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[3].deceleration"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("no deceleration time setting")));
    // a DBU waits for its own deceleration time
    EXPECT_FALSE(step(dbu, RecipeStep::Type::Stop).deceleration);
}

TEST_F(RecipeCheckerTest, DcSpeedCommandNeedsTheSpeedModeAndItsUnit)
{
    Recipe r = dc;
    r.positions[0].settings.removeFirst(); // config.speed_mode
    RecipeProblem p = only(r);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[0].speed"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("what 'Set speed' means depends on 'Speed "
                                                  "mode'")))
        << qPrintable(p.message);
    r = dc;
    r.positions[0].steps[0].unit = QStringLiteral("%"); // the speed loop's command is in 1/s
    p = only(r);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[0].unit"));
    r = dc;
    r.positions[0].steps[0].speed = 5000;
    p = only(r);
    EXPECT_TRUE(p.message.contains(QStringLiteral("'Set speed': 5000 1/s is not allowed; "
                                                  "allowed: -1000–1000 1/s")))
        << qPrintable(p.message);
}

TEST_F(RecipeCheckerTest, WaitForSpeedNeedsASaneToleranceAndTarget)
{
    step(dbu, RecipeStep::Type::WaitSpeed).tolerance = 2000;
    EXPECT_EQ(only(dbu).path, QStringLiteral("positions[0].steps[3].tolerance"));
    // the DC controller has no target speed of its own to wait for
    dc.positions[0].steps[1].target.reset();
    const RecipeProblem p = only(dc);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[1].target"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("does not report its target speed")));
}

TEST_F(RecipeCheckerTest, ReadStepComparesNumbersWithLimitsAndCodesWithText)
{
    step(dbu, RecipeStep::Type::Read).equals = QStringLiteral("Bus priority");
    RecipeProblem p = only(dbu);
    EXPECT_EQ(p.path, QStringLiteral("positions[0].steps[7].equals"));
    EXPECT_TRUE(p.message.contains(QStringLiteral("allowed: I/O priority (1), Communication "
                                                  "priority (2)")))
        << qPrintable(p.message);
    RecipeStep& read = step(dc, RecipeStep::Type::Read);
    read.equals = QStringLiteral("low");
    p = only(dc);
    EXPECT_TRUE(p.message.contains(QStringLiteral("'Motor current' is a number")))
        << qPrintable(p.message);
    read.equals.clear();
    read.limits[0].parameter = QStringLiteral("status.nothing");
    EXPECT_EQ(only(dc).path, QStringLiteral("positions[0].steps[4].parameter"));
}

TEST_F(RecipeCheckerTest, UnitValueGivenForAUnitIsCheckedAgainstTheRecipe)
{
    const RecipeChecker checker(ProfileRegistry::builtIn());
    EXPECT_EQ(checker.checkUnitValue(dbu, 1, QStringLiteral("spno3.speed"), 1500), QString());
    EXPECT_EQ(checker.checkUnitValue(dbu, 1, QStringLiteral("spno3.speed"), 1650),
              QStringLiteral("position 1 (machine number 1): per-unit value 'SPno3 speed': 1650 "
                             "r/min is outside the recipe's range 1400–1600 r/min"));
    // inside the range but not a value the drive takes (a DC brake current finer than 0.01 A)
    EXPECT_TRUE(checker.checkUnitValue(dc, 7, QStringLiteral("config.brake_current"), 1.005)
                    .contains(QStringLiteral("finer than the step")));
    EXPECT_TRUE(checker.checkUnitValue(dbu, 2, QStringLiteral("spno3.speed"), 1500)
                    .contains(QStringLiteral("no drive at machine number 2")));
    EXPECT_TRUE(checker.checkUnitValue(dbu, 1, QStringLiteral("spno4.speed"), 1500)
                    .contains(QStringLiteral("has no per-unit value 'SPno4 speed'")));
}

} // namespace
