#pragma once

#include <QString>
#include <QStringList>
#include <QVector>

class QTextStream;

namespace opentop {

// Aligned columns for human output. Numbers are right-aligned when a column says so. Every
// header and cell is shown through DisplayText::escaped(): one line, no control characters.
class TextTable
{
public:
    explicit TextTable(QStringList headers);
    void setRightAligned(int column, bool right = true);
    void addRow(QStringList cells);
    int rowCount() const { return m_rows.size(); }
    void print(QTextStream& out) const;

private:
    QStringList m_headers;
    QVector<QStringList> m_rows;
    QVector<bool> m_right;
};

} // namespace opentop
