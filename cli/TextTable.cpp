#include "cli/TextTable.h"

#include "cli/TerminalWidth.h"
#include "model/io/DisplayText.h"

#include <QTextStream>
#include <algorithm>

namespace opentop {

TextTable::TextTable(QStringList headers)
    : m_headers(std::move(headers))
    , m_right(m_headers.size(), false)
{
    for (QString& h : m_headers)
        h = DisplayText::escaped(h);
}

void TextTable::setRightAligned(int column, bool right)
{
    if (column >= 0 && column < m_right.size())
        m_right[column] = right;
}

void TextTable::addRow(QStringList cells)
{
    while (cells.size() < m_headers.size())
        cells << QString();
    // Cells hold names, serials and reasons from files, drives and databases: a control in one
    // would act on the terminal, a line break would break the table.
    for (QString& c : cells)
        c = DisplayText::escaped(c);
    m_rows << cells;
}

void TextTable::print(QTextStream& out) const
{
    QVector<int> width(m_headers.size(), 0);
    auto measure = [&](const QStringList& row) {
        for (int c = 0; c < m_headers.size(); ++c)
            width[c] = std::max(width[c], TerminalWidth::of(row.value(c)));
    };
    measure(m_headers);
    for (const QStringList& row : m_rows)
        measure(row);
    auto line = [&](const QStringList& row) {
        QString text;
        for (int c = 0; c < m_headers.size(); ++c) {
            const QString cell = row.value(c);
            const bool last = c == m_headers.size() - 1;
            if (m_right[c])
                text += TerminalWidth::padLeft(cell, width[c]);
            else
                text += last ? cell : TerminalWidth::padRight(cell, width[c]);
            if (!last)
                text += QStringLiteral("  ");
        }
        while (text.endsWith(QLatin1Char(' ')))
            text.chop(1);
        out << text << '\n';
    };
    line(m_headers);
    for (const QStringList& row : m_rows)
        line(row);
}

} // namespace opentop
