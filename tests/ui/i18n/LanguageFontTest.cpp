// Han characters drawn in the shapes of the language OpenTOP speaks, not of the system's locale
// (issue 29's fonts; on an English Debian, Traditional Chinese came out in Noto Sans CJK JP).
#include "ui/i18n/LanguageFont.h"

#include <QApplication>
#include <QFontDatabase>
#include <QFontInfo>
#include <QGlyphRun>
#include <QRawFont>
#include <QTextLayout>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// The families that draw `text` in the application font, in order. At a size of its own per
// call: Qt caches a font's fallbacks by its first family and size, and a program sets its
// language's font once, where this test sets four.
QStringList familiesDrawing(const QString& text)
{
    static int size = 12;
    QFont font = QApplication::font();
    font.setPixelSize(++size);
    QTextLayout layout(text, font);
    layout.beginLayout();
    layout.createLine();
    layout.endLayout();
    QStringList families;
    for (const QGlyphRun& run : layout.glyphRuns())
        families << run.rawFont().familyName();
    return families;
}

class FontKept
{
public:
    FontKept()
        : m_font(QApplication::font())
    {
    }
    ~FontKept() { QApplication::setFont(m_font); }
    const QFont& original() const { return m_font; }

private:
    QFont m_font;
};

} // namespace

TEST(LanguageFontTest, EachLanguageNamesItsOwnFamilyFirstAndKeepsTheOthers)
{
    for (bool windows : {false, true}) {
        const QStringList english = LanguageFont::familiesFor(QStringLiteral("en"), windows);
        for (const QString& language : {QStringLiteral("zh_TW"), QStringLiteral("zh_CN"),
                                        QStringLiteral("ko"), QStringLiteral("ja")}) {
            const QStringList families = LanguageFont::familiesFor(language, windows);
            // The same fonts in every language, none lost, none twice: only the order differs.
            QStringList sorted = families;
            QStringList sortedEnglish = english;
            sorted.sort();
            sortedEnglish.sort();
            EXPECT_EQ(sorted, sortedEnglish) << qPrintable(language);
            EXPECT_EQ(QStringList(families).removeDuplicates(), 0);
        }
    }
    EXPECT_EQ(LanguageFont::familiesFor(QStringLiteral("zh_TW"), false).first(),
              QStringLiteral("Noto Sans CJK TC"));
    EXPECT_EQ(LanguageFont::familiesFor(QStringLiteral("ja"), false).first(),
              QStringLiteral("Noto Sans CJK JP"));
    EXPECT_EQ(LanguageFont::familiesFor(QStringLiteral("zh_TW"), true).first(),
              QStringLiteral("Microsoft JhengHei UI"));
    EXPECT_EQ(LanguageFont::familiesFor(QStringLiteral("zh_CN"), true).first(),
              QStringLiteral("Microsoft YaHei UI"));
    EXPECT_EQ(LanguageFont::familiesFor(QStringLiteral("ko"), true).first(),
              QStringLiteral("Malgun Gothic"));
    EXPECT_EQ(LanguageFont::familiesFor(QStringLiteral("ja"), true).first(),
              QStringLiteral("Yu Gothic UI"));
}

TEST(LanguageFontTest, HanCharactersAreDrawnByTheLanguagesOwnFont)
{
    if (!QFontDatabase::families().contains(QStringLiteral("Noto Sans CJK TC")))
        GTEST_FAIL() << "no Noto Sans CJK on this machine (Debian: fonts-noto-cjk, which "
                        "scripts/setup.sh installs)";
    const FontKept kept;
    const QString han = QStringLiteral("機器門直");
    const struct
    {
        const char* language;
        const char* family;
    } cases[] = {{"zh_TW", "Noto Sans CJK TC"},
                 {"zh_CN", "Noto Sans CJK SC"},
                 {"ko", "Noto Sans CJK KR"},
                 {"ja", "Noto Sans CJK JP"}};
    for (const auto& c : cases) {
        QApplication::setFont(kept.original());
        LanguageFont::apply(QString::fromLatin1(c.language));
        EXPECT_EQ(familiesDrawing(han), QStringList{QString::fromLatin1(c.family)}) << c.language;
        // Latin text keeps the application's own font.
        EXPECT_EQ(familiesDrawing(QStringLiteral("Speed")),
                  QStringList{QFontInfo(kept.original()).family()})
            << c.language;
        // Hangul in a Chinese window: another CJK font draws it, never boxes.
        for (const QString& family : familiesDrawing(QStringLiteral("속도")))
            EXPECT_TRUE(family.startsWith(QStringLiteral("Noto Sans CJK"))) << qPrintable(family);
    }
}
