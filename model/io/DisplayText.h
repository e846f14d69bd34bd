#pragma once

#include <QString>

namespace opentop {

// How text that OpenTOP did not write itself is shown: names, serial numbers, products and
// reasons from recipe files, drives, CSV files, databases and the command line. A control
// character in such text would otherwise reach a terminal (ESC sequences retitle it or
// rewrite what was printed), a table (a line break fakes a row) or a spreadsheet, and a
// Unicode bidi override would show the text reordered.
//
// The form is C's: the controls C0 (U+0000–001F), DEL (U+007F) and C1 (U+0080–009F) as \xHH
// (\t, \n and \r by their short names), the bidi embeddings, overrides and isolates
// (U+202A–202E, U+2066–2069) and the line and paragraph separators (U+2028, U+2029) as \uHHHH,
// always two and four lower-case hex digits. A backslash itself is kept as it is: the result
// holds no control, so escaping it again changes nothing (a message that quotes escaped text
// is safe to escape as a whole), and paths such as C:\recipes read as they are written.
class DisplayText
{
public:
    // Every control shown as its escape: one line, whatever the text held.
    static QString escaped(const QString& text);
    // The same, but the line breaks kept: for a message OpenTOP made of several lines that
    // quotes text from outside (a line break inside a quoted name then starts a line of its
    // own, yet nothing reaches the terminal as a control).
    static QString escapedLines(const QString& text);
    // A CSV cell's text: escaped(), and a text a spreadsheet would take for a formula
    // (beginning with =, +, - or @) made text by a leading apostrophe, as spreadsheets
    // themselves do; a number such as "-12.5" or "+3" stays a number. A leading tab or carriage
    // return is escaped already (\t, \r). The caller quotes the cell for its separator.
    static QString csvCell(const QString& text);
    // True for a character escaped() shows as an escape.
    static bool isHidden(char16_t c);
};

} // namespace opentop
