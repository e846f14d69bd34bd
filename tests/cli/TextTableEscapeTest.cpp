// The command line's choke points for hostile text (issue 28, item 5): every table cell is
// shown escaped, one line, and the monitor's CSV cells are made safe for a spreadsheet.
#include "cli/MonitorOutput.h"
#include "cli/TextTable.h"

#include <QTextStream>
#include <gtest/gtest.h>

using namespace opentop;

TEST(TextTableEscapeTest, ControlCharactersInCellsAreShownEscapedOnOneLine)
{
    TextTable table({QStringLiteral("serial"), QStringLiteral("operator")});
    table.addRow({QStringLiteral("SN\x1b]0;owned\x07"), QStringLiteral("Ann\u202eeM")});
    table.addRow({QStringLiteral("two\nlines"), QStringLiteral("back\rspace")});
    QString text;
    QTextStream out(&text);
    table.print(out);
    out.flush();
    EXPECT_FALSE(text.contains(QChar(0x1b)));
    EXPECT_FALSE(text.contains(QChar(0x07)));
    EXPECT_FALSE(text.contains(QChar(0x202e)));
    EXPECT_FALSE(text.contains(QLatin1Char('\r')));
    const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 3) << qPrintable(text); // a line break in a cell adds no row
    EXPECT_TRUE(lines[1].startsWith(QStringLiteral("SN\\x1b]0;owned\\x07  "))) << qPrintable(text);
    EXPECT_TRUE(lines[1].endsWith(QStringLiteral("Ann\\u202eeM")));
    EXPECT_TRUE(lines[2].startsWith(QStringLiteral("two\\nlines")));
    EXPECT_TRUE(lines[2].endsWith(QStringLiteral("back\\rspace")));
    // The columns line up on the escaped text.
    EXPECT_EQ(lines[1].indexOf(QStringLiteral("Ann")),
              lines[0].indexOf(QStringLiteral("operator")));
}

TEST(TextTableEscapeTest, MonitorCsvCellsAreSafeForASpreadsheet)
{
    EXPECT_EQ(MonitorOutput::csvEscape(QStringLiteral("-12.5")), QStringLiteral("-12.5"));
    EXPECT_EQ(MonitorOutput::csvEscape(QStringLiteral("=cmd|'/C calc'!A0")),
              QStringLiteral("'=cmd|'/C calc'!A0"));
    EXPECT_EQ(MonitorOutput::csvEscape(QStringLiteral("=1,2")), QStringLiteral("\"'=1,2\""));
    EXPECT_EQ(MonitorOutput::csvEscape(QStringLiteral("a\nb\x1b")), QStringLiteral("a\\nb\\x1b"));
    EXPECT_EQ(MonitorOutput::csvEscape(QStringLiteral("say \"hi\"")),
              QStringLiteral("\"say \"\"hi\"\"\""));
}
