// UnitValuesCsv: per-unit values by serial number, with every malformed file refused naming the
// line, and every value checked against the recipe's range when it is looked up.
#include "model/eol/UnitValuesCsv.h"
#include "tests/model/eol/RecipeTestSupport.h"

#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

QString refusal(const QByteArray& data)
{
    QString error;
    EXPECT_FALSE(UnitValuesCsv::parse(data, &error)) << "accepted: " << data.constData();
    EXPECT_FALSE(error.isEmpty());
    return error;
}

class UnitValuesCsvTest : public ::testing::Test
{
protected:
    void SetUp() override { recipe = exampleRecipe("recipe-dbu200.json"); }

    // The values for `serial` from `data`, or the refusal in *error.
    std::optional<QVector<UnitValuesCsv::Value>> lookUp(const QByteArray& data, const char* serial,
                                                        QString* error)
    {
        const std::optional<UnitValuesCsv> csv = UnitValuesCsv::parse(data, error);
        EXPECT_TRUE(csv) << qPrintable(*error);
        if (!csv)
            return std::nullopt;
        return csv->valuesFor(recipe, ProfileRegistry::builtIn(), QString::fromLatin1(serial),
                              error);
    }

    Recipe recipe;
};

TEST_F(UnitValuesCsvTest, ReadsValuesBySerialNumber)
{
    QString error;
    const auto values = lookUp("serial,spno3.speed\nA100,1450\nA101,1550\n", "A101", &error);
    ASSERT_TRUE(values) << qPrintable(error);
    ASSERT_EQ(values->size(), 1);
    EXPECT_EQ(values->first().machineNumber, 1);
    EXPECT_EQ(values->first().parameter, QStringLiteral("spno3.speed"));
    EXPECT_EQ(values->first().value, 1550);
}

TEST_F(UnitValuesCsvTest, ReadsWhatSpreadsheetsWrite)
{
    // a byte-order mark, CRLF, quoted fields, blank lines, ';' with a decimal comma, "1:" columns
    const QByteArray data = "\xEF\xBB\xBFSerial;\"1:spno3.speed\"\r\n\r\n\"A;7\";1500,0\r\n"
                            "\"B \"\"x\"\"\";1410\r\n";
    QString error;
    const std::optional<UnitValuesCsv> csv = UnitValuesCsv::parse(data, &error);
    ASSERT_TRUE(csv) << qPrintable(error);
    EXPECT_EQ(csv->rows(), 2);
    EXPECT_TRUE(csv->contains(QStringLiteral("B \"x\"")));
    const auto values =
        csv->valuesFor(recipe, ProfileRegistry::builtIn(), QStringLiteral("A;7"), &error);
    ASSERT_TRUE(values) << qPrintable(error);
    EXPECT_EQ(values->first().value, 1500);
}

TEST_F(UnitValuesCsvTest, MalformedFilesAreRefusedWithTheLine)
{
    EXPECT_TRUE(refusal("").contains(QStringLiteral("empty")));
    EXPECT_TRUE(
        refusal("unit,spno3.speed\n").contains(QStringLiteral("must start with \"serial\"")));
    EXPECT_TRUE(refusal("serial\nA1\n").contains(QStringLiteral("names no per-unit value")));
    EXPECT_TRUE(refusal("serial,a,a\n").contains(QStringLiteral("column \"a\" appears twice")));
    EXPECT_TRUE(refusal("serial,a,\n").contains(QStringLiteral("column 3 has no name")));
    EXPECT_EQ(refusal("serial,a\nA1,1\nA2,1,2\n"),
              QStringLiteral("line 3: 3 fields, but the header has 2"));
    EXPECT_EQ(refusal("serial,a\nA1,1\n\nA1,2\n"),
              QStringLiteral("line 4: serial number \"A1\" is already on line 2"));
    EXPECT_EQ(refusal("serial,a\n,1\n"), QStringLiteral("line 2: no serial number"));
    EXPECT_TRUE(refusal("serial,a\n\"A1,1\n").contains(QStringLiteral("line 2: a quoted field")));
    EXPECT_TRUE(
        refusal("serial,a\n\"A1\"x,1\n").contains(QStringLiteral("line 2: a quoted field")));
    EXPECT_TRUE(refusal(QByteArray("serial,a\nA\0,1\n", 14)).contains(QStringLiteral("NUL")));
    EXPECT_TRUE(refusal(QByteArray(UnitValuesCsv::kMaxFileBytes + 1, 'x'))
                    .contains(QStringLiteral("larger than")));
}

TEST_F(UnitValuesCsvTest, ValuesAreCheckedAgainstTheRecipe)
{
    QString error;
    EXPECT_FALSE(lookUp("serial,spno3.speed\nA1,1700\n", "A1", &error));
    EXPECT_EQ(error, QStringLiteral("line 2: position 1 (machine number 1): per-unit value 'SPno3 "
                                    "speed': 1700 r/min is outside the recipe's range "
                                    "1400–1600 r/min"));
    EXPECT_FALSE(lookUp("serial,spno3.speed\nA1,fast\n", "A1", &error));
    EXPECT_EQ(error, QStringLiteral("line 2, column \"spno3.speed\": \"fast\" is not a number"));
    EXPECT_FALSE(lookUp("serial,spno3.speed\nA1,\n", "A1", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no value for serial number \"A1\"")))
        << qPrintable(error);
    EXPECT_FALSE(lookUp("serial,spno3.speed\nA1,1500\n", "A2", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("\"A2\" is not in the CSV file")))
        << qPrintable(error);
    EXPECT_FALSE(lookUp("serial,spno4.speed\nA1,1500\n", "A1", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("has no column \"spno3.speed\" (or "
                                              "\"1:spno3.speed\")")))
        << qPrintable(error);
}

TEST_F(UnitValuesCsvTest, PlainColumnNamesMustBeUnambiguous)
{
    RecipePosition second = recipe.positions.first();
    second.machineNumber = 2;
    recipe.positions << second;
    QString error;
    EXPECT_FALSE(lookUp("serial,spno3.speed\nA1,1500\n", "A1", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("is ambiguous"))) << qPrintable(error);
    const auto values = lookUp("serial,1:spno3.speed,2:spno3.speed\nA1,1500,1420\n", "A1", &error);
    ASSERT_TRUE(values) << qPrintable(error);
    ASSERT_EQ(values->size(), 2);
    EXPECT_EQ(values->at(1).machineNumber, 2);
    EXPECT_EQ(values->at(1).value, 1420);
}

TEST_F(UnitValuesCsvTest, LoadsAFile)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("trim.csv"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("serial,spno3.speed\nA1,1500\n");
    file.close();
    QString error;
    const std::optional<UnitValuesCsv> csv = UnitValuesCsv::load(path, &error);
    ASSERT_TRUE(csv) << qPrintable(error);
    EXPECT_TRUE(csv->contains(QStringLiteral("A1")));
    EXPECT_FALSE(UnitValuesCsv::load(dir.filePath(QStringLiteral("none.csv")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("cannot read")));
}

} // namespace
