// RecipeBuilder: a recipe made from a backup of the simulated drives (a DBU200 at 1, a DBU400
// at 150, a DC controller at 7) holds each drive's settings as the drive had them, names its
// variant and firmware, leaves the communication settings out, and passes the checker with
// its default steps; it survives a round trip through a recipe file.
#include "model/eol/RecipeBuilder.h"
#include "model/files/BackupFile.h"
#include "tests/model/eol/RecipeTestSupport.h"
#include "tests/model/files/BackupTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class RecipeBuilderTest : public SimBusFixture
{
protected:
    BackupFile backupOfTheBus()
    {
        BackupFile file;
        file.tool = BackupFile::toolName();
        file.created = QDateTime::currentDateTimeUtc();
        file.connection = BackupFile::connectionOf(client->settings());
        for (int slave : {1, 150, 7}) {
            const BackupReader::Result r = backup(slave);
            EXPECT_TRUE(r.ok) << slave << qPrintable(r.failures.join(QLatin1Char('\n')));
            file.devices << r.device;
        }
        // through the file format, as `recipe create --from-backup` reads it
        QString error;
        const std::optional<BackupFile> read = BackupFile::fromJson(
            file.toJson(ProfileRegistry::builtIn()), ProfileRegistry::builtIn(), &error);
        EXPECT_TRUE(read) << qPrintable(error);
        return read.value_or(file);
    }

    static const RecipeSetting* setting(const RecipePosition& p, const char* name)
    {
        for (const RecipeSetting& s : p.settings) {
            if (s.name == QLatin1String(name))
                return &s;
        }
        return nullptr;
    }
};

TEST_F(RecipeBuilderTest, FromABackupOfTheSimulatedDrives)
{
    set(1, 0xCA03, 1700); // SPno2 speed of the DBU200 at 1
    set(1, 0x0313, 1);    // SPno2 direction CCW
    const BackupFile file = backupOfTheBus();
    QString error;
    const std::optional<Recipe> recipe =
        RecipeBuilder(ProfileRegistry::builtIn())
            .fromBackup(file, QStringLiteral("Golden"), QStringLiteral("1"), &error);
    ASSERT_TRUE(recipe) << qPrintable(error);
    EXPECT_TRUE(problemsOf(*recipe).isEmpty()) << qPrintable(textOf(problemsOf(*recipe)));
    ASSERT_EQ(recipe->positions.size(), 3);

    const RecipePosition& dbu = recipe->positions.at(0);
    EXPECT_EQ(dbu.machineNumber, 1);
    EXPECT_EQ(dbu.family, QStringLiteral("dbu"));
    EXPECT_EQ(dbu.variants, QStringList{QStringLiteral("dbu200")});
    EXPECT_EQ(dbu.firmware, QStringList{file.device(1)->firmware});
    EXPECT_FALSE(dbu.firmware.first().isEmpty());
    ASSERT_TRUE(setting(dbu, "spno2.speed"));
    EXPECT_EQ(setting(dbu, "spno2.speed")->value.toDouble(), 1700);
    EXPECT_EQ(setting(dbu, "spno2.speed")->unit, QStringLiteral("r/min"));
    ASSERT_TRUE(setting(dbu, "spno2.direction"));
    EXPECT_EQ(setting(dbu, "spno2.direction")->value.toString(), QStringLiteral("CCW"));
    EXPECT_FALSE(setting(dbu, "comm.rate")) << "communication settings stay out";
    // every other setting the backup holds is in the recipe
    EXPECT_EQ(dbu.settings.size(), file.device(1)->parameters.size() - 1);

    // the default steps run the selected data at the drive's own speed and direction
    ASSERT_EQ(dbu.steps.size(), 7);
    EXPECT_EQ(dbu.steps.at(1).spno, 2);
    EXPECT_EQ(dbu.steps.at(2).direction, QStringLiteral("ccw"));
    EXPECT_EQ(dbu.steps.at(3).target, std::optional<double>(1700));
    EXPECT_EQ(dbu.steps.last().type, RecipeStep::Type::NoAlarm);

    EXPECT_EQ(recipe->positions.at(1).variants, QStringList{QStringLiteral("dbu400")});
    const RecipePosition& dc = recipe->positions.at(2);
    EXPECT_EQ(dc.machineNumber, 7);
    EXPECT_EQ(dc.family, QStringLiteral("dcpid"));
    EXPECT_TRUE(dc.variants.isEmpty());
    EXPECT_FALSE(setting(dc, "config.baud"));
    ASSERT_FALSE(dc.steps.isEmpty());
    EXPECT_EQ(dc.steps.first().type, RecipeStep::Type::Speed);
    EXPECT_EQ(dc.steps.last().type, RecipeStep::Type::Stop);

    // and the recipe reads back from its file as it was
    const std::optional<Recipe> again = RecipeFile::fromJson(RecipeFile::toJson(*recipe), &error);
    ASSERT_TRUE(again) << qPrintable(error);
    EXPECT_EQ(RecipeFile::toObject(*again), RecipeFile::toObject(*recipe));
}

TEST_F(RecipeBuilderTest, FromADriveReadOnTheBus)
{
    const BackupReader::Result dc = backup(7);
    ASSERT_TRUE(dc.ok);
    QString error;
    const std::optional<RecipePosition> position =
        RecipeBuilder(ProfileRegistry::builtIn()).positionFrom(dc.device, &error);
    ASSERT_TRUE(position) << qPrintable(error);
    Recipe recipe;
    recipe.product = QStringLiteral("Lift");
    recipe.revision = QStringLiteral("1");
    recipe.positions << *position;
    EXPECT_TRUE(problemsOf(recipe).isEmpty()) << qPrintable(textOf(problemsOf(recipe)));
    // the speed command is in the unit of the drive's speed mode
    const RecipeSetting* mode = setting(*position, "config.speed_mode");
    ASSERT_TRUE(mode);
    EXPECT_TRUE(mode->value.isString()) << "an enumeration by its label";
}

TEST_F(RecipeBuilderTest, RefusesADriveOfAnUnknownFamily)
{
    BackupDevice device;
    device.slave = 3;
    device.family = QStringLiteral("vfd");
    QString error;
    EXPECT_FALSE(RecipeBuilder(ProfileRegistry::builtIn()).positionFrom(device, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("unknown family"))) << qPrintable(error);
    EXPECT_FALSE(RecipeBuilder(ProfileRegistry::builtIn())
                     .fromDevices({}, QStringLiteral("x"), QStringLiteral("1"), &error));
}

} // namespace
