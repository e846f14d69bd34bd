#include "model/eol/SerialRule.h"

#include "model/eol/Recipe.h"

#include <QRegularExpression>
#include <optional>

namespace opentop {

namespace {

struct BadCharacter
{
    int index = 0;      // from 0, in the text's UTF-16 units
    char32_t point = 0; // the code point
};

// The first character no serial may hold: control (C0, DEL, C1), format (a bidirectional
// override makes a terminal or a report show other text than is stored), line or paragraph
// separator, a surrogate without its pair, or one Unicode does not assign.
std::optional<BadCharacter> badCharacter(const QString& text)
{
    for (int i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        char32_t point = c.unicode();
        const int at = i;
        if (c.isHighSurrogate() && i + 1 < text.size() && text.at(i + 1).isLowSurrogate())
            point = QChar::surrogateToUcs4(c, text.at(++i));
        switch (QChar::category(point)) {
        case QChar::Other_Control:
        case QChar::Other_Format:
        case QChar::Other_Surrogate:
        case QChar::Other_NotAssigned:
        case QChar::Separator_Line:
        case QChar::Separator_Paragraph:
            return BadCharacter{at, point};
        default:
            break;
        }
    }
    return std::nullopt;
}

QString codePoint(char32_t point)
{
    return QStringLiteral("U+%1").arg(uint(point), 4, 16, QLatin1Char('0')).toUpper();
}

// Matched against the whole serial, whether or not the pattern says ^…$.
QRegularExpression wholeMatch(const QString& pattern)
{
    return QRegularExpression(QRegularExpression::anchoredPattern(pattern));
}

} // namespace

QString SerialRule::problem(const QString& serial, const Recipe& recipe)
{
    return problem(serial, recipe.serialPattern, recipe.serialExample);
}

QString SerialRule::problem(const QString& serial, const QString& pattern, const QString& example)
{
    if (serial.isEmpty())
        return tr("no serial number");
    if (serial.size() > kMaxLength)
        return tr("a serial number has at most %1 characters; this one has %2")
            .arg(QString::number(kMaxLength), QString::number(serial.size()));
    // The serial itself is not quoted: it would carry its control characters into the message.
    if (const std::optional<BadCharacter> bad = badCharacter(serial))
        return tr("a serial number may not hold control characters, format characters or line "
                  "breaks; character %1 is %2")
            .arg(QString::number(bad->index + 1), codePoint(bad->point));
    if (serial.front().isSpace() || serial.back().isSpace())
        return tr("serial number \"%1\" begins or ends with white space; a serial number is "
                  "tested exactly as given")
            .arg(serial);
    if (pattern.isEmpty())
        return QString();
    const QRegularExpression whole = wholeMatch(pattern);
    // A pattern the recipe reader would refuse matches nothing: never a way around the rule.
    if (!QRegularExpression(pattern).isValid() || !whole.isValid() ||
        !whole.match(serial).hasMatch())
        return example.isEmpty()
                   ? tr("serial number \"%1\" does not match the recipe's serial pattern %2")
                         .arg(serial, pattern)
                   : tr("serial number \"%1\" does not match the recipe's serial pattern %2 "
                        "(e.g. %3)")
                         .arg(serial, pattern, example);
    return QString();
}

QString SerialRule::recipeProblem(const QString& pattern, const QString& example, QString* field)
{
    auto fail = [field](const char* name, const QString& message) {
        if (field)
            *field = QString::fromLatin1(name);
        return message;
    };
    if (!pattern.isEmpty()) {
        if (pattern.size() > kMaxPatternLength)
            return fail(
                "serialPattern",
                tr("\"serialPattern\" has %1 characters; at most %2 are allowed")
                    .arg(QString::number(pattern.size()), QString::number(kMaxPatternLength)));
        if (const std::optional<BadCharacter> bad = badCharacter(pattern))
            return fail("serialPattern",
                        tr("\"serialPattern\" may not hold control characters, format characters "
                           "or line breaks (no serial number holds one); character %1 is %2")
                            .arg(QString::number(bad->index + 1), codePoint(bad->point)));
        const QRegularExpression re(pattern);
        if (!re.isValid())
            return fail(
                "serialPattern",
                tr("\"serialPattern\" %1 is not a valid regular expression: %2 at "
                   "character %3")
                    .arg(pattern, re.errorString(), QString::number(re.patternErrorOffset() + 1)));
        // "\Qabc" is valid, but quotes what would make it match the whole serial.
        if (!wholeMatch(pattern).isValid())
            return fail("serialPattern",
                        tr("\"serialPattern\" %1 cannot be matched against a whole serial number")
                            .arg(pattern));
    }
    if (!example.isEmpty()) {
        if (pattern.isEmpty())
            return fail("serialExample",
                        tr("\"serialExample\" needs a \"serialPattern\" that it matches"));
        const QString why = problem(example, pattern);
        if (!why.isEmpty())
            return fail("serialExample", tr("\"serialExample\": %1").arg(why));
    }
    if (field)
        field->clear();
    return QString();
}

QString SerialRule::patternText(const Recipe& recipe)
{
    if (recipe.serialPattern.isEmpty())
        return tr("any, at most %1 characters").arg(kMaxLength);
    if (recipe.serialExample.isEmpty())
        return recipe.serialPattern;
    return tr("%1 (e.g. %2)").arg(recipe.serialPattern, recipe.serialExample);
}

} // namespace opentop
