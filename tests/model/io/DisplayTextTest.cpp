// Hostile text reaches no terminal, window or spreadsheet (issue 28, item 5): how text that
// OpenTOP did not write is shown (DisplayText), one place for the command line, the window, CSV
// files and the certificate.
#include "model/io/DisplayText.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

// A serial number that retitles an xterm and rings its bell when printed raw.
const QString kRetitle = QStringLiteral("SN\x1b]0;owned\x07");

bool holdsHidden(const QString& text)
{
    for (const QChar c : text) {
        if (DisplayText::isHidden(c.unicode()))
            return true;
    }
    return false;
}

} // namespace

TEST(DisplayTextTest, ControlCharactersAreShownAsCEscapes)
{
    EXPECT_EQ(DisplayText::escaped(kRetitle), QStringLiteral("SN\\x1b]0;owned\\x07"));
    EXPECT_EQ(DisplayText::escaped(QStringLiteral("a\tb\nc\rd")), QStringLiteral("a\\tb\\nc\\rd"));
    EXPECT_EQ(DisplayText::escaped(QString(QChar(0))), QStringLiteral("\\x00"));
    EXPECT_EQ(DisplayText::escaped(QStringLiteral("x\x1fy")), QStringLiteral("x\\x1fy"));
    EXPECT_EQ(DisplayText::escaped(QStringLiteral("del\x7f")), QStringLiteral("del\\x7f"));
    // C1: U+009B is CSI for a terminal that takes 8-bit controls, U+0085 a line break.
    EXPECT_EQ(DisplayText::escaped(QStringLiteral("a\u009b2Jb\u0085")),
              QStringLiteral("a\\x9b2Jb\\x85"));
    EXPECT_EQ(DisplayText::escaped(QStringLiteral("\u0080\u009f")), QStringLiteral("\\x80\\x9f"));
}

TEST(DisplayTextTest, BidiOverridesAndLineSeparatorsAreShownAsUnicodeEscapes)
{
    // "txt.exe" reversed would read "exe.txt" with the override acting.
    EXPECT_EQ(DisplayText::escaped(QStringLiteral("report\u202eexe.txt")),
              QStringLiteral("report\\u202eexe.txt"));
    for (char16_t c : {u'\u202a', u'\u202b', u'\u202c', u'\u202d', u'\u202e', u'\u2066', u'\u2067',
                       u'\u2068', u'\u2069', u'\u2028', u'\u2029'}) {
        const QString shown = DisplayText::escaped(QString(QChar(c)));
        EXPECT_EQ(shown, QStringLiteral("\\u%1").arg(uint(c), 4, 16, QLatin1Char('0')))
            << shown.toStdString();
    }
}

TEST(DisplayTextTest, OrdinaryTextIsLeftAsItIs)
{
    for (const QString& text :
         {QStringLiteral("SN-2026-000123"), QStringLiteral("Pumpe 200 – Ölstand ≥ 5 %"),
          QStringLiteral("제어 우선순위 運轉資料 パラメータ"), QStringLiteral("مضخة ٢٠٠"),
          QStringLiteral("משאבה"), QStringLiteral("C:\\recipes\\pump.json"),
          QStringLiteral("e\u0301 \u00a0 \u00ff \u0100 \u200b"), QString()})
        EXPECT_EQ(DisplayText::escaped(text), text) << text.toStdString();
}

TEST(DisplayTextTest, NoHiddenCharacterSurvivesAndEveryOneIsShown)
{
    for (uint u = 0; u <= 0xffff; ++u) {
        const char16_t c = char16_t(u);
        if (QChar::isSurrogate(c))
            continue;
        const QString text = QStringLiteral("<") + QChar(c) + QStringLiteral(">");
        const QString shown = DisplayText::escaped(text);
        ASSERT_FALSE(holdsHidden(shown)) << u;
        // Hidden characters become visible text; everything else is untouched.
        ASSERT_EQ(shown == text, !DisplayText::isHidden(c)) << u;
    }
    EXPECT_TRUE(DisplayText::isHidden(0x1b));
    EXPECT_TRUE(DisplayText::isHidden(0x9b));
    EXPECT_TRUE(DisplayText::isHidden(0x202e));
    EXPECT_FALSE(DisplayText::isHidden(u'a'));
    EXPECT_FALSE(DisplayText::isHidden(0xa0));
}

TEST(DisplayTextTest, EscapingTwiceChangesNothing)
{
    // A message that quotes an escaped name may be escaped as a whole again.
    const QString once = DisplayText::escaped(kRetitle + QStringLiteral("\u202e\n\\x41"));
    EXPECT_EQ(DisplayText::escaped(once), once);
    EXPECT_EQ(DisplayText::escapedLines(once), once);
    EXPECT_EQ(DisplayText::csvCell(DisplayText::csvCell(QStringLiteral("=1+2"))),
              QStringLiteral("'=1+2"));
}

TEST(DisplayTextTest, EscapedLinesKeepsTheLineBreaksOfAMessage)
{
    EXPECT_EQ(DisplayText::escapedLines(QStringLiteral("first line\nserial ") + kRetitle +
                                        QStringLiteral("\r\n")),
              QStringLiteral("first line\nserial SN\\x1b]0;owned\\x07\\r\n"));
    EXPECT_EQ(DisplayText::escapedLines(QStringLiteral("\t\u202e")), QStringLiteral("\\t\\u202e"));
}

TEST(DisplayTextTest, CsvCellMakesFormulasTextButKeepsNumbers)
{
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("=cmd|'/C calc'!A0")),
              QStringLiteral("'=cmd|'/C calc'!A0"));
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("@SUM(A1:A9)")), QStringLiteral("'@SUM(A1:A9)"));
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("+1+2")), QStringLiteral("'+1+2"));
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("-2+3")), QStringLiteral("'-2+3"));
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("-")), QStringLiteral("'-"));
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("=HYPERLINK(\"http://x\")")),
              QStringLiteral("'=HYPERLINK(\"http://x\")"));
    // Numbers stay numbers, for a spreadsheet to add up.
    for (const QString& number :
         {QStringLiteral("-12.5"), QStringLiteral("+3"), QStringLiteral("-0.001"),
          QStringLiteral("-1e-05"), QStringLiteral("-2.5E+10"), QStringLiteral("-.5"),
          QStringLiteral("1498.25"), QStringLiteral("0")})
        EXPECT_EQ(DisplayText::csvCell(number), number) << number.toStdString();
    // A tab or carriage return in front is escaped, so never reaches the spreadsheet raw.
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("\t=1+2")), QStringLiteral("\\t=1+2"));
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("\r=1+2")), QStringLiteral("\\r=1+2"));
    EXPECT_EQ(DisplayText::csvCell(QStringLiteral("=1\x1b")), QStringLiteral("'=1\\x1b"));
    // Ordinary text, and signs inside it, are left alone.
    for (const QString& text :
         {QStringLiteral("SN-1"), QStringLiteral("a=b"), QStringLiteral("pump A"), QString()})
        EXPECT_EQ(DisplayText::csvCell(text), text) << text.toStdString();
}
