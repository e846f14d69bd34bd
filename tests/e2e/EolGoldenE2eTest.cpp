// Limits from a golden unit over a real port: `opentop-cli eol recipe create --drives 1
// --measure` on a pseudo-terminal against opentop-sim. Without --yes it names the drive, turns
// nothing and writes nothing; with it, the golden drive runs the recipe's steps once and the
// hold's load limit comes down from the default 100 % to the measured load plus the stated
// margin, so that a unit drawing 30 % more than the golden one now fails where the default
// passed it, and the golden unit itself still passes.
#include "model/eol/RecipeFile.h"
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr int kCurrentSpeed = 0x0109; // DBU status.current_speed (fc 04)

std::optional<RecipeLimit> loadLimit(const Recipe& recipe)
{
    for (const RecipeStep& s : recipe.positions.value(0).steps)
        for (const RecipeLimit& l : s.limits)
            if (l.parameter == QLatin1String("status.load"))
                return l;
    return std::nullopt;
}

// `recipe` moved to machine number `id`, saved as a new file.
QString movedTo(const QTemporaryDir& dir, Recipe recipe, int id)
{
    recipe.positions[0].machineNumber = id;
    const QString path = dir.filePath(QStringLiteral("moved-%1.json").arg(id));
    QString error;
    EXPECT_TRUE(RecipeFile::save(recipe, path, &error)) << error.toStdString();
    return path;
}

CliResult runUnit(const QString& port, const QString& recipe, const QString& serial,
                  const QString& db)
{
    return runCliOn(port,
                    {QStringLiteral("eol"), QStringLiteral("run"), recipe,
                     QStringLiteral("--serial"), serial, QStringLiteral("--db"), db,
                     QStringLiteral("--station"), QStringLiteral("golden-e2e")},
                    120000);
}

} // namespace

TEST(EolGoldenE2e, MeasuredLimitsCatchAUnitTheDefaultLoadLimitPassed)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1-2"),
                           QStringLiteral("--defect"), QStringLiteral("2:load=+30")},
                          &error))
        << error.toStdString();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("golden.json"));
    const QStringList create{QStringLiteral("eol"),
                             QStringLiteral("recipe"),
                             QStringLiteral("create"),
                             QStringLiteral("--drives"),
                             QStringLiteral("1"),
                             QStringLiteral("--product"),
                             QStringLiteral("Conveyor"),
                             QStringLiteral("--revision"),
                             QStringLiteral("A"),
                             QStringLiteral("-o"),
                             path,
                             QStringLiteral("--measure")};

    // Asked without --yes: the drive and what it would do are named; nothing turns.
    CliResult r = runCliOn(sim.pty, create, 60000);
    EXPECT_EQ(r.code, 2) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("machine number 1 (dbu200): runs its motor")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--yes"))) << r.err.toStdString();
    EXPECT_FALSE(QFile::exists(path));
    EXPECT_EQ(sim.get(1, kCurrentSpeed, 4), 0);

    // With --yes: measured, tightened, said, written; the motor stopped afterwards.
    r = runCliOn(sim.pty,
                 QStringList(create) << QStringLiteral("--yes") << QStringLiteral("--json"),
                 120000);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_EQ(sim.get(1, kCurrentSpeed, 4), 0);
    const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_TRUE(json.value(QStringLiteral("valid")).toBool()) << r.out.toStdString();
    QJsonObject load;
    for (const QJsonValue& v : json.value(QStringLiteral("measuredLimits")).toArray())
        if (v.toObject()
                .value(QStringLiteral("quantity"))
                .toString()
                .startsWith(QStringLiteral("Load rate")))
            load = v.toObject();
    ASSERT_FALSE(load.isEmpty()) << r.out.toStdString();
    const double measured = load.value(QStringLiteral("measured")).toDouble();
    const double upper = load.value(QStringLiteral("upper")).toDouble();
    EXPECT_GT(measured, 0);
    EXPECT_EQ(load.value(QStringLiteral("defaultUpper")).toDouble(), 100);
    // The stated margin: 25 % of the value, at least 5 % of the 0–200 % full scale, whole %.
    EXPECT_GE(upper, measured + std::max(measured * 0.25, 10.0));
    EXPECT_LE(upper, measured + std::max(measured * 0.25, 10.0) + 1);

    const std::optional<Recipe> recipe = RecipeFile::load(path, &error);
    ASSERT_TRUE(recipe) << error.toStdString();
    ASSERT_TRUE(loadLimit(*recipe));
    EXPECT_EQ(loadLimit(*recipe)->upper, upper);
    EXPECT_TRUE(recipe->description.contains(QStringLiteral("measured on the golden unit")))
        << recipe->description.toStdString();

    // The golden drive passes its own recipe; the drive drawing 30 % more fails on its load,
    // which the default limit of 100 % let through.
    const QString db = dir.filePath(QStringLiteral("results.db"));
    r = runUnit(sim.pty, path, QStringLiteral("G-1"), db);
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    Recipe defaults = *recipe;
    for (RecipeStep& s : defaults.positions[0].steps)
        for (RecipeLimit& l : s.limits)
            if (l.parameter == QLatin1String("status.load"))
                l.upper = 100;
    r = runUnit(sim.pty, movedTo(dir, defaults, 2), QStringLiteral("H-1"), db);
    EXPECT_EQ(r.code, 0) << "the default limit passes it: " << (r.out + r.err).toStdString();
    r = runUnit(sim.pty, movedTo(dir, *recipe, 2), QStringLiteral("H-2"), db);
    EXPECT_EQ(r.code, 5) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Load rate max"))) << r.out.toStdString();
    EXPECT_EQ(sim.get(2, kCurrentSpeed, 4), 0);
}
