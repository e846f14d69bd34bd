// No text as boxes (issue 13): for each language, a font on this machine draws every character
// of every translated message. Fails on a machine without the CJK fonts (fonts-noto-cjk) the
// package depends on and scripts/setup.sh installs.
#include <QFile>
#include <QFontDatabase>
#include <QFontMetrics>
#include <QSet>
#include <QXmlStreamReader>
#include <gtest/gtest.h>

namespace {

QSet<char32_t> charactersOf(const QString& language)
{
    QSet<char32_t> characters;
    QFile file(QStringLiteral(OPENTOP_SOURCE_DIR "/translations/opentop_%1.ts").arg(language));
    if (!file.open(QIODevice::ReadOnly))
        return characters;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement() && xml.name() == QLatin1String("translation")) {
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            for (char32_t c : text.toUcs4())
                if (c > 0x20)
                    characters.insert(c);
        }
    }
    return characters;
}

struct Case
{
    const char* language;
    QFontDatabase::WritingSystem script;
};

class TranslationGlyphsTest : public ::testing::TestWithParam<Case>
{
};

} // namespace

TEST_P(TranslationGlyphsTest, AFontOfTheLanguageDrawsEveryCharacterOfItsMessages)
{
    const Case c = GetParam();
    const QSet<char32_t> characters = charactersOf(QString::fromLatin1(c.language));
    ASSERT_GT(characters.size(), 300) << c.language;
    const QStringList families = QFontDatabase::families(c.script);
    ASSERT_FALSE(families.isEmpty())
        << "no font for " << c.language << " on this machine (Debian: fonts-noto-cjk)";
    // Qt falls back through the fonts of the script; the best of them must cover everything.
    int fewestMissing = characters.size();
    QString best;
    QString missingSample;
    for (const QString& family : families) {
        const QFontMetrics metrics{QFont(family)};
        int missing = 0;
        QString sample;
        for (char32_t ch : characters)
            if (!metrics.inFontUcs4(ch)) {
                ++missing;
                if (sample.size() < 20)
                    sample += QString::fromUcs4(&ch, 1);
            }
        if (missing < fewestMissing) {
            fewestMissing = missing;
            best = family;
            missingSample = sample;
        }
        if (missing == 0)
            break;
    }
    EXPECT_EQ(fewestMissing, 0) << c.language << ": best font " << qPrintable(best)
                                << " lacks: " << qPrintable(missingSample);
}

INSTANTIATE_TEST_SUITE_P(Languages, TranslationGlyphsTest,
                         ::testing::Values(Case{"zh_TW", QFontDatabase::TraditionalChinese},
                                           Case{"zh_CN", QFontDatabase::SimplifiedChinese},
                                           Case{"ko", QFontDatabase::Korean},
                                           Case{"ja", QFontDatabase::Japanese}),
                         [](const ::testing::TestParamInfo<Case>& param) {
                             return std::string(param.param.language);
                         });
