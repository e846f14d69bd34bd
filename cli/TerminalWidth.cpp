#include "cli/TerminalWidth.h"

#include <QChar>
#include <QList>

namespace opentop {

int TerminalWidth::ofCharacter(char32_t c)
{
    const QChar::Category category = QChar::category(c);
    if (category == QChar::Mark_NonSpacing || category == QChar::Mark_Enclosing ||
        category == QChar::Other_Format)
        return 0;
    // The East Asian Wide (W) and Fullwidth (F) ranges of Unicode's EastAsianWidth.txt that
    // text in these languages uses.
    const bool wide = (c >= 0x1100 && c <= 0x115F) || // Hangul Jamo
                      (c >= 0x2E80 && c <= 0x303E) || // CJK radicals, punctuation
                      (c >= 0x3041 && c <= 0x33FF) || // kana, CJK compatibility
                      (c >= 0x3400 && c <= 0x4DBF) || // CJK extension A
                      (c >= 0x4E00 && c <= 0x9FFF) || // CJK unified ideographs
                      (c >= 0xA000 && c <= 0xA4CF) || // Yi
                      (c >= 0xAC00 && c <= 0xD7A3) || // Hangul syllables
                      (c >= 0xF900 && c <= 0xFAFF) || // CJK compatibility ideographs
                      (c >= 0xFE30 && c <= 0xFE4F) || // CJK compatibility forms
                      (c >= 0xFF00 && c <= 0xFF60) || // fullwidth forms
                      (c >= 0xFFE0 && c <= 0xFFE6) || // fullwidth signs
                      (c >= 0x20000 && c <= 0x3FFFD); // CJK extensions B and beyond
    return wide ? 2 : 1;
}

int TerminalWidth::of(const QString& text)
{
    int columns = 0;
    for (char32_t c : text.toUcs4())
        columns += ofCharacter(c);
    return columns;
}

QString TerminalWidth::padRight(const QString& text, int columns)
{
    const int missing = columns - of(text);
    return missing > 0 ? text + QString(missing, QLatin1Char(' ')) : text;
}

QString TerminalWidth::padLeft(const QString& text, int columns)
{
    const int missing = columns - of(text);
    return missing > 0 ? QString(missing, QLatin1Char(' ')) + text : text;
}

} // namespace opentop
