// The drive's variant over a real port: `opentop-cli eol run` on a pseudo-terminal against
// opentop-sim, whose DBUs report only "DBU" as real ones do. The shipped example recipes pass
// with the matching drives (a mixed DBU200/DBU400 unit included); a DBU400 at a DBU200
// position never passes as a DBU200, and the probe leaves its registers as they were;
// --variant outside the recipe is refused before anything is sent.
#include "CliProcess.h"
#include "SimProcess.h"
#include "eol/RecipeFile.h"
#include "eol/ResultDatabase.h"
#include "eol/ResultQueries.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr int kLowerLimit = 0x1009; // DBU core.lower_limit (fc 03): the variant probe's setting

QString example(const char* name)
{
    return QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/") + QString::fromLatin1(name);
}

// `eol run` of `recipe` with every per-unit value in the middle of its range.
CliResult runUnit(const QString& port, const QString& recipePath, const QString& serial,
                  const QString& db, const QStringList& extra = {})
{
    QString error;
    const std::optional<Recipe> recipe = RecipeFile::load(recipePath, &error);
    EXPECT_TRUE(recipe) << error.toStdString();
    QStringList args{QStringLiteral("eol"),
                     QStringLiteral("run"),
                     recipePath,
                     QStringLiteral("--serial"),
                     serial,
                     QStringLiteral("--db"),
                     db,
                     QStringLiteral("--station"),
                     QStringLiteral("e2e"),
                     QStringLiteral("--json")};
    for (const RecipePosition& p : recipe ? recipe->positions : QVector<RecipePosition>())
        for (const RecipeUnitValue& u : p.unitValues)
            args << QStringLiteral("--value")
                 << QStringLiteral("%1:%2=%3")
                        .arg(p.machineNumber)
                        .arg(u.name)
                        .arg(std::round((u.min + u.max) / 2));
    return runCliOn(port, args + extra, 120000);
}

QJsonObject resultOf(const QString& out)
{
    QJsonObject found;
    for (const QString& line : out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        if (o.value(QStringLiteral("event")).toString() == QLatin1String("result"))
            found = o;
    }
    return found;
}

std::optional<UnitRecord> recordOf(const QString& db, const QString& serial)
{
    QString error;
    const std::unique_ptr<ResultDatabase> database = ResultDatabase::open(db, &error);
    if (!database)
        return std::nullopt;
    const auto history = ResultQueries(*database).history(serial, &error);
    if (!history || history->isEmpty())
        return std::nullopt;
    return history->last();
}

class EolVariantE2e : public ::testing::Test
{
protected:
    void start(const QString& devices)
    {
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"), devices}, &error))
            << error.toStdString();
        db = dir.filePath(QStringLiteral("results.db"));
    }

    SimProcess sim;
    QTemporaryDir dir;
    QString db;
};

} // namespace

TEST_F(EolVariantE2e, TheExampleDbu200RecipePassesAndTheRecordSaysTheVariantWasProbed)
{
    start(QStringLiteral("dbu200@1"));
    const CliResult r = runUnit(sim.pty, example("recipe-dbu200.json"), QStringLiteral("SN-1"), db);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    const auto record = recordOf(db, QStringLiteral("SN-1"));
    ASSERT_TRUE(record);
    ASSERT_EQ(record->drives.size(), 1);
    EXPECT_EQ(record->drives[0].variant, QStringLiteral("dbu200"));
    EXPECT_EQ(record->drives[0].variantSource, VariantSource::Probed);
    EXPECT_EQ(sim.get(1, kLowerLimit, 3), 0); // the probe's value written back
}

TEST_F(EolVariantE2e, TheEightDriveExamplePassesWithDbu200sAndDbu400sMixed)
{
    start(QStringLiteral("dbu200@1-4,dbu400@5-8"));
    const CliResult r =
        runUnit(sim.pty, example("recipe-eight-dbu.json"), QStringLiteral("SN-8"), db);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    const auto record = recordOf(db, QStringLiteral("SN-8"));
    ASSERT_TRUE(record);
    ASSERT_EQ(record->drives.size(), 8);
    for (const UnitDrive& d : record->drives) {
        EXPECT_EQ(d.variant,
                  d.machineNumber <= 4 ? QStringLiteral("dbu200") : QStringLiteral("dbu400"))
            << d.machineNumber;
        EXPECT_EQ(d.variantSource, VariantSource::Probed) << d.machineNumber;
        EXPECT_EQ(sim.get(d.machineNumber, kLowerLimit, 3), 0) << d.machineNumber;
    }
}

TEST_F(EolVariantE2e, TheDcControllerExamplePasses)
{
    start(QStringLiteral("dcpid@7"));
    // The simulator's pty takes the command line's default line format, as the other e2e tests.
    const CliResult r = runUnit(sim.pty, example("recipe-dcpid.json"), QStringLiteral("SN-D"), db);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
}

TEST_F(EolVariantE2e, ADbu400AtADbu200PositionNeverPassesAsADbu200)
{
    start(QStringLiteral("dbu400@1"));
    const int lowerBefore = sim.get(1, kLowerLimit, 3);
    const CliResult r = runUnit(sim.pty, example("recipe-dbu200.json"), QStringLiteral("SN-4"), db);
    EXPECT_NE(r.code, 0) << (r.out + r.err).toStdString();
    const QJsonObject result = resultOf(r.out);
    EXPECT_NE(result.value(QStringLiteral("status")).toString(), QStringLiteral("pass"));
    const QString reason = result.value(QStringLiteral("reason")).toString();
    EXPECT_TRUE(reason.contains(QStringLiteral("DBU400")) &&
                reason.contains(QStringLiteral("DBU200")))
        << r.out.toStdString();
    const auto record = recordOf(db, QStringLiteral("SN-4"));
    ASSERT_TRUE(record);
    ASSERT_EQ(record->drives.size(), 1);
    EXPECT_EQ(record->drives[0].variant, QStringLiteral("dbu400"));
    EXPECT_EQ(record->drives[0].variantSource, VariantSource::Probed);
    EXPECT_TRUE(record->writtenValues.isEmpty());
    EXPECT_EQ(sim.get(1, kLowerLimit, 3), lowerBefore);
}

TEST_F(EolVariantE2e, AVariantTheRecipeDoesNotAllowIsRefusedBeforeAnythingIsSent)
{
    start(QStringLiteral("dbu200@1"));
    const CliResult r = runUnit(sim.pty, example("recipe-dbu200.json"), QStringLiteral("SN-V"), db,
                                {QStringLiteral("--variant"), QStringLiteral("dbu400")});
    EXPECT_EQ(r.code, 2) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was sent"))) << r.err.toStdString();
    EXPECT_FALSE(recordOf(db, QStringLiteral("SN-V")));
}
