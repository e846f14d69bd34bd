// Results exported as CSV open in a spreadsheet (issue 28, item 5): a serial number or a name
// that a spreadsheet would compute ("=cmd|'/C calc'!A0") arrives as text, a control character
// as its escape, and the measured numbers, negative ones too, as numbers.
#include "model/eol/ResultCsv.h"
#include "tests/support/EolSampleUnit.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

// The fields of every CRLF record; quoted fields as RFC 4180 has them.
QVector<QStringList> records(const QByteArray& bytes)
{
    const QString text = QString::fromUtf8(bytes);
    QVector<QStringList> rows;
    QStringList row;
    QString field;
    bool quoted = false;
    for (int i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (quoted) {
            if (c == QLatin1Char('"') && i + 1 < text.size() && text[i + 1] == QLatin1Char('"')) {
                field += c;
                ++i;
            } else if (c == QLatin1Char('"')) {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(',')) {
            row << field;
            field.clear();
        } else if (c == QLatin1Char('\r') && i + 1 < text.size() &&
                   text[i + 1] == QLatin1Char('\n')) {
            rows << (row << field);
            row.clear();
            field.clear();
            ++i;
        } else {
            field += c;
        }
    }
    return rows;
}

UnitRecord hostileUnit()
{
    UnitRecord r = test::eolSampleUnit(QStringLiteral("=cmd|'/C calc'!A0"));
    r.id = QStringLiteral("id-7");
    r.operatorName = QStringLiteral("@SUM(1+1)");
    r.station = QStringLiteral("+station");
    r.failureReason = QStringLiteral("SN\x1b]0;owned\x07 failed\r\n-2+3");
    r.measurements = {{1, QStringLiteral("hold CW"), QStringLiteral("=1+2"), -12.5,
                       QStringLiteral("A"), -20.0, -5.0, true},
                      {1, QStringLiteral("hold CW"), QStringLiteral("load max"), 87.5,
                       QStringLiteral("%"), std::nullopt, 120.0, true}};
    return r;
}

} // namespace

TEST(ResultCsvSpreadsheetTest, UnitsExportMakesFormulasTextAndEscapesControls)
{
    const QByteArray csv = ResultCsv::units({hostileUnit()});
    // Only the record ends are line breaks; no control reaches the file.
    EXPECT_FALSE(csv.contains('\x1b'));
    EXPECT_FALSE(csv.contains('\x07'));
    EXPECT_EQ(csv.count('\r'), csv.count("\r\n"));
    EXPECT_EQ(csv.count('\n'), 2) << csv.constData();
    const QVector<QStringList> rows = records(csv);
    ASSERT_EQ(rows.size(), 2);
    ASSERT_EQ(rows[1].size(), 11);
    EXPECT_EQ(rows[1][0], QStringLiteral("id-7"));
    EXPECT_EQ(rows[1][1], QStringLiteral("'=cmd|'/C calc'!A0"));
    EXPECT_EQ(rows[1][2], QStringLiteral("'+station"));
    EXPECT_EQ(rows[1][3], QStringLiteral("'@SUM(1+1)"));
    EXPECT_EQ(rows[1][7], QStringLiteral("7b"));
    EXPECT_EQ(rows[1][10], QStringLiteral("SN\\x1b]0;owned\\x07 failed\\r\\n-2+3"));
}

TEST(ResultCsvSpreadsheetTest, MeasuredNumbersStayNumbers)
{
    const QVector<QStringList> rows = records(ResultCsv::measurements({hostileUnit()}));
    ASSERT_EQ(rows.size(), 3);
    ASSERT_EQ(rows[1].size(), 10);
    EXPECT_EQ(rows[1][1], QStringLiteral("'=cmd|'/C calc'!A0"));
    EXPECT_EQ(rows[1][4], QStringLiteral("'=1+2")); // the quantity is text
    EXPECT_EQ(rows[1][5], QStringLiteral("-12.5"));
    EXPECT_EQ(rows[1][7], QStringLiteral("-20"));
    EXPECT_EQ(rows[1][8], QStringLiteral("-5"));
    EXPECT_EQ(rows[2][5], QStringLiteral("87.5"));
    EXPECT_EQ(rows[2][8], QStringLiteral("120"));
}

TEST(ResultCsvSpreadsheetTest, YieldExportMakesARecipeNamedLikeAFormulaText)
{
    YieldRow row;
    row.recipe = QStringLiteral("=HYPERLINK(\"http://evil\",\"pump\")");
    row.revision = QStringLiteral("-1");
    row.serials = 2;
    row.records = 2;
    row.passed = 2;
    row.firstPass = 2;
    row.lastPass = 2;
    const QVector<QStringList> rows = records(ResultCsv::yield({row}));
    ASSERT_EQ(rows.size(), 2);
    EXPECT_EQ(rows[1][0], QStringLiteral("'=HYPERLINK(\"http://evil\",\"pump\")"));
    EXPECT_EQ(rows[1][1], QStringLiteral("-1")); // a number, as the file had it
    EXPECT_EQ(rows[1][4], QStringLiteral("2"));
}
