// StationRecipe: a recipe the checker refuses is not loaded (the one before stays); a unit's
// values are the typed ones plus its CSV row, and a CSV value cannot be had without the file
// or for a serial the file does not hold.
#include "model/station/StationRecipe.h"
#include "tests/model/eol/RecipeTestSupport.h"

#include <QFile>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

TEST(StationRecipeTest, ACsvValueComesFromTheSerialsRowAndATypedOneAsTyped)
{
    StationRecipe station;
    QStringList problems;
    ASSERT_TRUE(station.load(exampleRecipePath("recipe-dbu200.json"), &problems))
        << qPrintable(problems.join(QLatin1Char('\n')));
    ASSERT_TRUE(station.has());
    EXPECT_TRUE(station.checksum().startsWith(QStringLiteral("sha256:")));
    QString error;
    // The example's SPno3 speed comes from the CSV file by serial.
    EXPECT_FALSE(station.unitValues(QStringLiteral("C200-0001"), {}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("CSV"))) << qPrintable(error);

    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("units.csv"));
    QFile f(csv);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("serial,spno3.speed\nC200-0001,1450\nC200-0002,1530\n");
    f.close();
    ASSERT_TRUE(station.loadUnitValues(csv, &error)) << qPrintable(error);
    const QHash<int, QHash<QString, double>> typed{{1, {{QStringLiteral("typed.one"), 7}}}};
    const auto values = station.unitValues(QStringLiteral("C200-0002"), typed, &error);
    ASSERT_TRUE(values) << qPrintable(error);
    EXPECT_EQ(values->value(1).value(QStringLiteral("spno3.speed")), 1530);
    EXPECT_EQ(values->value(1).value(QStringLiteral("typed.one")), 7);
    EXPECT_FALSE(station.unitValues(QStringLiteral("C200-9999"), {}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("C200-9999"))) << qPrintable(error);

    // A file that is not a valid recipe leaves the loaded one, and its values, as they were.
    const QString broken = dir.filePath(QStringLiteral("broken.json"));
    QFile b(broken);
    ASSERT_TRUE(b.open(QIODevice::WriteOnly));
    b.write("{\"format\": \"nonsense\"}");
    b.close();
    EXPECT_FALSE(station.load(broken, &problems));
    EXPECT_FALSE(problems.isEmpty());
    EXPECT_EQ(station.path(), exampleRecipePath("recipe-dbu200.json"));
    EXPECT_TRUE(station.hasUnitValues());
}
