#include "model/eol/ResultCsv.h"
#include "tests/support/EolSampleUnit.h"

#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// An RFC 4180 reader, independent of the writer: the fields of every record.
QVector<QStringList> parseCsv(const QByteArray& bytes)
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
            row.append(field);
            field.clear();
        } else if (c == QLatin1Char('\r') && i + 1 < text.size() &&
                   text[i + 1] == QLatin1Char('\n')) {
            row.append(field);
            field.clear();
            rows.append(row);
            row.clear();
            ++i;
        } else {
            field += c;
        }
    }
    EXPECT_TRUE(field.isEmpty() && row.isEmpty()) << "the last record has no CRLF";
    return rows;
}

} // namespace

TEST(ResultCsvTest, QuotesOnlyWhatMustBeQuoted)
{
    EXPECT_EQ(ResultCsv::field(QStringLiteral("plain text")), QStringLiteral("plain text"));
    EXPECT_EQ(ResultCsv::field(QStringLiteral("a,b")), QStringLiteral("\"a,b\""));
    EXPECT_EQ(ResultCsv::field(QStringLiteral("say \"hi\"")), QStringLiteral("\"say \"\"hi\"\"\""));
    EXPECT_EQ(ResultCsv::field(QStringLiteral("two\nlines")), QStringLiteral("\"two\nlines\""));
    EXPECT_EQ(ResultCsv::line({QStringLiteral("x"), QString(), QStringLiteral("y")}),
              QByteArray("x,,y\r\n"));
}

TEST(ResultCsvTest, UnitsAndMeasurementsReadBackFieldForField)
{
    UnitRecord r = test::eolSampleUnit(QStringLiteral("SN,\"7\""));
    r.id = QStringLiteral("id-1");
    const auto units = parseCsv(ResultCsv::units({r}));
    ASSERT_EQ(units.size(), 2);
    EXPECT_EQ(units[0].size(), 11);
    ASSERT_EQ(units[1].size(), 11);
    EXPECT_EQ(units[1][1], r.serial);
    EXPECT_EQ(units[1][3], r.operatorName);
    EXPECT_EQ(units[1][4], QStringLiteral("2026-11-24T13:05:07.123Z"));
    EXPECT_EQ(units[1][6], r.recipeName);
    EXPECT_EQ(units[1][9], QStringLiteral("fail"));
    EXPECT_EQ(units[1][10], r.failureReason);
    const auto measured = parseCsv(ResultCsv::measurements({r}));
    ASSERT_EQ(measured.size(), 1 + r.measurements.size());
    EXPECT_EQ(measured[1][5], QStringLiteral("1498.25"));
    EXPECT_EQ(measured[2][7], QString());            // no lower limit
    EXPECT_EQ(measured[3][5].toDouble(), 0.1 + 0.2); // exact
    EXPECT_EQ(measured[4][9], QStringLiteral("fail"));
}

TEST(ResultCsvTest, SavesThroughOutputFile)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("units.csv"));
    QString error;
    ASSERT_TRUE(ResultCsv::save(path, ResultCsv::units({}), &error)) << error.toStdString();
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.readAll().startsWith("unit_id,serial,"));
    EXPECT_FALSE(ResultCsv::save(dir.path(), QByteArray("x"), &error)); // a directory
    EXPECT_TRUE(error.contains(QLatin1String("directory"))) << error.toStdString();
}
