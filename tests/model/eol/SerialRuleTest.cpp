// The serial-number rule every entry point asks (issue 28, item 5): control characters, white
// space at either end and overlong serials are refused whatever the recipe says; a recipe's
// pattern is matched against the whole serial; a refusal names the pattern (and the example)
// and never repeats the hostile characters it refuses.
#include "model/eol/SerialRule.h"
#include "model/eol/Recipe.h"

#include <QString>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

Recipe withPattern(const QString& pattern, const QString& example = QString())
{
    Recipe recipe;
    recipe.product = QStringLiteral("Conveyor C-200");
    recipe.revision = QStringLiteral("A");
    recipe.serialPattern = pattern;
    recipe.serialExample = example;
    return recipe;
}

} // namespace

TEST(SerialRule, AnOrdinarySerialIsTakenWhenTheRecipeHasNoPattern)
{
    const Recipe any = withPattern(QString());
    for (const char* serial : {"SN-1001", "C200-0042", "A", "SN 1001", "Ä-Ω-7"})
        EXPECT_EQ(SerialRule::problem(QString::fromUtf8(serial), any), QString()) << serial;
    EXPECT_EQ(SerialRule::problem(QString(SerialRule::kMaxLength, QLatin1Char('7')), any),
              QString());
}

TEST(SerialRule, ControlCharactersAreRefusedWithoutRepeatingThem)
{
    const Recipe any = withPattern(QString());
    struct Case
    {
        QString serial;
        const char* names;
    };
    const Case cases[] = {
        {QStringLiteral("SN\x1b]0;owned\a"), "character 3 is U+001B"}, // OSC title sequence
        {QStringLiteral("SN\t1"), "character 3 is U+0009"},
        {QStringLiteral("SN\n1"), "character 3 is U+000A"},
        {QStringLiteral("SN\r"), "character 3 is U+000D"},
        {QString(QLatin1String("SN\0"
                               "1",
                               4)),
         "character 3 is U+0000"},
        {QStringLiteral("SN\x7f"), "character 3 is U+007F"},                    // DEL
        {QStringLiteral("SN") + QChar(0x9b) + QStringLiteral("31m"), "U+009B"}, // C1 CSI
        {QStringLiteral("SN") + QChar(0x85), "U+0085"},                         // C1 next line
        {QStringLiteral("SN") + QChar(0x202e) + QStringLiteral("1"), "U+202E"}, // RTL override
        {QStringLiteral("SN") + QChar(0x2028), "U+2028"},                       // line separator
        {QStringLiteral("SN") + QChar(0xd800) + QStringLiteral("1"), "U+D800"}, // lone surrogate
    };
    for (const Case& c : cases) {
        const QString why = SerialRule::problem(c.serial, any);
        EXPECT_TRUE(why.contains(QString::fromLatin1(c.names)) &&
                    why.contains(QStringLiteral("control characters")))
            << qPrintable(why);
        for (const QChar ch : why)
            EXPECT_TRUE(ch.unicode() >= 0x20 && ch.unicode() != 0x7f &&
                        (ch.unicode() < 0x80 || ch.unicode() > 0x9f))
                << "the refusal carries U+" << std::hex << ch.unicode();
    }
    // A character outside the BMP is one character, not a lone surrogate.
    EXPECT_EQ(SerialRule::problem(QStringLiteral("SN-") + QString::fromUcs4(U"\U0001F600"), any),
              QString());
}

TEST(SerialRule, WhiteSpaceAtEitherEndIsRefusedNotTrimmed)
{
    const Recipe any = withPattern(QString());
    for (const QString& serial :
         {QStringLiteral(" SN1"), QStringLiteral("SN1 "), QStringLiteral("  "),
          QStringLiteral("SN1") + QChar(0x00a0), QChar(0x3000) + QStringLiteral("SN1")}) {
        const QString why = SerialRule::problem(serial, any);
        EXPECT_TRUE(why.contains(QStringLiteral("white space"))) << qPrintable(why);
    }
    EXPECT_EQ(SerialRule::problem(QString(), any), QStringLiteral("no serial number"));
}

TEST(SerialRule, AnOverlongSerialIsRefusedEvenWhenThePatternWouldTakeIt)
{
    const QString longSerial(SerialRule::kMaxLength + 1, QLatin1Char('7'));
    const QString why = SerialRule::problem(longSerial, withPattern(QStringLiteral("[0-9]+")));
    EXPECT_TRUE(why.contains(QStringLiteral("at most 64 characters")) &&
                why.contains(QStringLiteral("this one has 65")))
        << qPrintable(why);
}

TEST(SerialRule, ThePatternMustMatchTheWholeSerialAndARefusalNamesIt)
{
    const Recipe recipe = withPattern(QStringLiteral("TR[0-9]{8}"), QStringLiteral("TR00012345"));
    EXPECT_EQ(SerialRule::problem(QStringLiteral("TR12345678"), recipe), QString());
    // Not anchored in the recipe, yet a serial that only contains a match is refused.
    for (const char* serial : {"xTR12345678", "TR123456789", "TR1234567", "tr12345678"}) {
        const QString why = SerialRule::problem(QString::fromLatin1(serial), recipe);
        EXPECT_EQ(why, QStringLiteral("serial number \"%1\" does not match the recipe's serial "
                                      "pattern TR[0-9]{8} (e.g. TR00012345)")
                           .arg(QString::fromLatin1(serial)));
    }
    const QString why =
        SerialRule::problem(QStringLiteral("SN1"), withPattern(QStringLiteral("^TR[0-9]{8}$")));
    EXPECT_EQ(why, QStringLiteral("serial number \"SN1\" does not match the recipe's serial "
                                  "pattern ^TR[0-9]{8}$"));
    // An alternative only at the top level must not loosen the anchoring: "A|B" is A or B whole.
    const Recipe either = withPattern(QStringLiteral("A1|B2"));
    EXPECT_EQ(SerialRule::problem(QStringLiteral("B2"), either), QString());
    EXPECT_FALSE(SerialRule::problem(QStringLiteral("A1x"), either).isEmpty());
    EXPECT_FALSE(SerialRule::problem(QStringLiteral("xB2"), either).isEmpty());
}

TEST(SerialRule, ThePatternNeverLetsAControlCharacterThrough)
{
    // Whatever the recipe's pattern, the fixed rule comes first.
    const Recipe anything = withPattern(QStringLiteral("(?s).*"));
    EXPECT_EQ(SerialRule::problem(QStringLiteral("SN1"), anything), QString());
    EXPECT_FALSE(SerialRule::problem(QStringLiteral("SN\x1b[2J"), anything).isEmpty());
    EXPECT_FALSE(SerialRule::problem(QStringLiteral("SN1\n"), anything).isEmpty());
    // A pattern the reader refuses (given to the rule anyway) matches nothing.
    EXPECT_FALSE(SerialRule::problem(QStringLiteral("SN1"), QStringLiteral("SN1(")).isEmpty());
}

TEST(SerialRule, ARecipesPatternAndExampleAreCheckedNamingTheField)
{
    QString field;
    EXPECT_EQ(SerialRule::recipeProblem(QString(), QString(), &field), QString());
    EXPECT_EQ(SerialRule::recipeProblem(QStringLiteral("^TR[0-9]{8}$"),
                                        QStringLiteral("TR00012345"), &field),
              QString());

    QString why = SerialRule::recipeProblem(QStringLiteral("^TR[0-9{8}$"), QString(), &field);
    EXPECT_EQ(field, QStringLiteral("serialPattern"));
    EXPECT_TRUE(why.startsWith(QStringLiteral("\"serialPattern\" ^TR[0-9{8}$ is not a valid "
                                              "regular expression: ")))
        << qPrintable(why);
    // Valid alone, but it would quote the anchoring that matches the whole serial.
    why = SerialRule::recipeProblem(QStringLiteral("\\QTR"), QString(), &field);
    EXPECT_EQ(field, QStringLiteral("serialPattern"));
    EXPECT_FALSE(why.isEmpty());
    why = SerialRule::recipeProblem(QStringLiteral("TR\x1b"), QString(), &field);
    EXPECT_TRUE(why.contains(QStringLiteral("U+001B"))) << qPrintable(why);
    why = SerialRule::recipeProblem(QString(SerialRule::kMaxPatternLength + 1, QLatin1Char('a')),
                                    QString(), &field);
    EXPECT_TRUE(why.contains(QStringLiteral("at most 1000"))) << qPrintable(why);

    why = SerialRule::recipeProblem(QStringLiteral("^TR[0-9]{8}$"), QStringLiteral("TR1"), &field);
    EXPECT_EQ(field, QStringLiteral("serialExample"));
    EXPECT_TRUE(why.startsWith(QStringLiteral("\"serialExample\": serial number \"TR1\" does not "
                                              "match")))
        << qPrintable(why);
    why = SerialRule::recipeProblem(QString(), QStringLiteral("TR1"), &field);
    EXPECT_EQ(field, QStringLiteral("serialExample"));
    EXPECT_TRUE(why.contains(QStringLiteral("needs a \"serialPattern\""))) << qPrintable(why);
}

TEST(SerialRule, PatternTextSaysWhatIsTested)
{
    EXPECT_EQ(SerialRule::patternText(withPattern(QString())),
              QStringLiteral("any, at most 64 characters"));
    EXPECT_EQ(SerialRule::patternText(withPattern(QStringLiteral("^TR[0-9]{8}$"))),
              QStringLiteral("^TR[0-9]{8}$"));
    EXPECT_EQ(SerialRule::patternText(
                  withPattern(QStringLiteral("^TR[0-9]{8}$"), QStringLiteral("TR00012345"))),
              QStringLiteral("^TR[0-9]{8}$ (e.g. TR00012345)"));
}
