#pragma once

#include <QString>

namespace opentop {

// How many terminal columns text takes: Chinese, Japanese and Korean characters (East Asian
// wide and fullwidth) take two, combining marks none. Columns of a table line up only when they
// are padded by this, not by the number of characters.
class TerminalWidth
{
public:
    static int of(const QString& text);
    // `text` followed (or preceded) by spaces up to `columns`; unchanged when it is wider.
    static QString padRight(const QString& text, int columns);
    static QString padLeft(const QString& text, int columns);
    static int ofCharacter(char32_t c);
};

} // namespace opentop
