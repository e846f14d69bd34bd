// Tables on a terminal in every language (issue 13): a Chinese, Japanese or Korean character
// takes two columns, so the columns after it line up only when padded by terminal width.
#include "cli/TextTable.h"
#include "cli/TerminalWidth.h"

#include <QTextStream>
#include <gtest/gtest.h>

using namespace opentop;

TEST(TerminalWidthTest, WideCharactersTakeTwoColumnsAndMarksNone)
{
    EXPECT_EQ(TerminalWidth::of(QStringLiteral("I/O priority")), 12);
    EXPECT_EQ(TerminalWidth::of(QStringLiteral("제어 우선순위")), 13); // 6 syllables, a space
    EXPECT_EQ(TerminalWidth::of(QStringLiteral("運轉資料")), 8);
    EXPECT_EQ(TerminalWidth::of(QStringLiteral("パラメータ")), 10);
    EXPECT_EQ(TerminalWidth::of(QStringLiteral("（注）")), 6);  // fullwidth parentheses
    EXPECT_EQ(TerminalWidth::of(QStringLiteral("e\u0301")), 1); // a combining accent
    EXPECT_EQ(TerminalWidth::padRight(QStringLiteral("速度"), 6), QStringLiteral("速度  "));
    EXPECT_EQ(TerminalWidth::padLeft(QStringLiteral("速度"), 6), QStringLiteral("  速度"));
    EXPECT_EQ(TerminalWidth::padRight(QStringLiteral("速度"), 3), QStringLiteral("速度"));
}

TEST(TextTableTest, ColumnsLineUpOnTheTerminalWithKoreanAndChineseCells)
{
    TextTable table({QStringLiteral("파라미터"), QStringLiteral("값"), QStringLiteral("원시값")});
    table.addRow({QStringLiteral("core.control_priority"), QStringLiteral("I/O 우선"),
                  QStringLiteral("0001")});
    table.addRow(
        {QStringLiteral("core.stop_hold"), QStringLiteral("유지력 없음"), QStringLiteral("0000")});
    table.addRow(
        {QStringLiteral("spno1.speed"), QStringLiteral("1500 r/min"), QStringLiteral("05DC")});
    QString text;
    QTextStream out(&text);
    table.print(out);
    out.flush();
    const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 4);
    // The last column starts at the same terminal column on every line.
    QVector<int> starts;
    for (const QString& line : lines) {
        const int at = int(line.lastIndexOf(QStringLiteral("  "))) + 2;
        starts << TerminalWidth::of(line.left(at));
    }
    for (int i = 1; i < starts.size(); ++i)
        EXPECT_EQ(starts[i], starts[0]) << qPrintable(lines[i]);
}
