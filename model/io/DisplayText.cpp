#include "model/io/DisplayText.h"

#include <QRegularExpression>

namespace opentop {

namespace {

QString escapeOf(char16_t c)
{
    switch (c) {
    case u'\t':
        return QStringLiteral("\\t");
    case u'\n':
        return QStringLiteral("\\n");
    case u'\r':
        return QStringLiteral("\\r");
    default:
        break;
    }
    if (c <= 0xff)
        return QStringLiteral("\\x%1").arg(uint(c), 2, 16, QLatin1Char('0'));
    return QStringLiteral("\\u%1").arg(uint(c), 4, 16, QLatin1Char('0'));
}

QString escape(const QString& text, bool keepLineBreaks)
{
    qsizetype first = 0;
    while (first < text.size() && !DisplayText::isHidden(text.at(first).unicode()))
        ++first;
    if (first == text.size())
        return text; // the common case: nothing to do, no copy
    QString out = text.left(first);
    out.reserve(text.size() + 8);
    for (qsizetype i = first; i < text.size(); ++i) {
        const char16_t c = text.at(i).unicode();
        if (DisplayText::isHidden(c) && !(keepLineBreaks && c == u'\n'))
            out += escapeOf(c);
        else
            out += QChar(c);
    }
    return out;
}

} // namespace

bool DisplayText::isHidden(char16_t c)
{
    return c < 0x20 || (c >= 0x7f && c <= 0x9f) || (c >= 0x202a && c <= 0x202e) ||
           (c >= 0x2066 && c <= 0x2069) || c == 0x2028 || c == 0x2029;
}

QString DisplayText::escaped(const QString& text)
{
    return escape(text, false);
}

QString DisplayText::escapedLines(const QString& text)
{
    return escape(text, true);
}

QString DisplayText::csvCell(const QString& text)
{
    const QString cell = escaped(text);
    if (cell.isEmpty())
        return cell;
    const QChar first = cell.at(0);
    if (first != QLatin1Char('=') && first != QLatin1Char('+') && first != QLatin1Char('-') &&
        first != QLatin1Char('@'))
        return cell;
    // "-12.5" and "+3" are numbers, which a spreadsheet must still be able to add up; "=1+2",
    // "-2+3" and "@SUM(A1)" are not, and would be computed.
    static const QRegularExpression number(
        QStringLiteral("^[+-](\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?$"));
    return number.match(cell).hasMatch() ? cell : QLatin1Char('\'') + cell;
}

} // namespace opentop
