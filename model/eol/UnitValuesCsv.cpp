#include "model/eol/UnitValuesCsv.h"
#include "model/io/DisplayText.h"
#include "model/io/InputFile.h"

#include "model/eol/Recipe.h"
#include "model/eol/RecipeChecker.h"

#include <QFile>
#include <QLocale>
#include <QSet>
#include <algorithm>
#include <cmath>

namespace opentop {

// Messages quote the file's text escaped (DisplayText): they are shown in terminals and windows.

namespace {

// The fields of one line; *error when a quote is not closed or text follows a closing quote.
QStringList splitLine(const QString& line, QChar separator, bool* ok)
{
    QStringList fields;
    QString field;
    bool quoted = false;
    bool afterQuote = false;
    *ok = true;
    for (int i = 0; i < line.size(); ++i) {
        const QChar c = line.at(i);
        if (quoted) {
            if (c == QLatin1Char('"')) {
                if (i + 1 < line.size() && line.at(i + 1) == QLatin1Char('"')) {
                    field += c;
                    ++i;
                } else {
                    quoted = false;
                    afterQuote = true;
                }
            } else {
                field += c;
            }
        } else if (c == separator) {
            fields << field.trimmed();
            field.clear();
            afterQuote = false;
        } else if (c == QLatin1Char('"') && field.trimmed().isEmpty() && !afterQuote) {
            quoted = true;
            field.clear();
        } else if (afterQuote && !c.isSpace()) {
            *ok = false;
            return {};
        } else {
            field += c;
        }
    }
    if (quoted) {
        *ok = false;
        return {};
    }
    fields << field.trimmed();
    return fields;
}

} // namespace

std::optional<UnitValuesCsv> UnitValuesCsv::parse(const QByteArray& data, QString* error)
{
    auto refuse = [&](const QString& message) -> std::optional<UnitValuesCsv> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    if (data.size() > kMaxFileBytes)
        return refuse(tr("the CSV file is larger than %1 MB").arg(kMaxFileBytes / (1024 * 1024)));
    if (data.contains('\0'))
        return refuse(tr("not a CSV text file (it holds NUL bytes)"));
    QString text = QString::fromUtf8(data);
    if (text.startsWith(QChar(0xFEFF)))
        text.remove(0, 1);
    const QStringList lines = text.split(QLatin1Char('\n'));
    UnitValuesCsv csv;
    bool header = true;
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines.at(i);
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
        if (line.trimmed().isEmpty())
            continue;
        const int number = i + 1;
        if (header) {
            if (!line.contains(QLatin1Char(',')) && line.contains(QLatin1Char(';')))
                csv.m_separator = QLatin1Char(';');
        }
        bool ok = true;
        const QStringList fields = splitLine(line, csv.m_separator, &ok);
        if (!ok)
            return refuse(tr("line %1: a quoted field is not closed properly").arg(number));
        if (header) {
            header = false;
            if (fields.first().compare(QLatin1String("serial"), Qt::CaseInsensitive) != 0)
                return refuse(tr("line %1: the header must start with \"serial\", not \"%2\"")
                                  .arg(number)
                                  .arg(DisplayText::escaped(fields.first().left(40))));
            if (fields.size() < 2)
                return refuse(tr("line %1: the header names no per-unit value").arg(number));
            if (fields.size() > kMaxColumns)
                return refuse(tr("line %1: more than %2 columns").arg(number).arg(kMaxColumns));
            QSet<QString> seen;
            for (int c = 1; c < fields.size(); ++c) {
                if (fields.at(c).isEmpty())
                    return refuse(tr("line %1: column %2 has no name").arg(number).arg(c + 1));
                if (seen.contains(fields.at(c)))
                    return refuse(tr("line %1: column \"%2\" appears twice")
                                      .arg(number)
                                      .arg(DisplayText::escaped(fields.at(c).left(80))));
                seen.insert(fields.at(c));
                csv.m_columns << fields.at(c);
            }
            continue;
        }
        if (fields.size() != csv.m_columns.size() + 1)
            return refuse(tr("line %1: %2 fields, but the header has %3")
                              .arg(number)
                              .arg(fields.size())
                              .arg(csv.m_columns.size() + 1));
        const QString serial = fields.first();
        if (serial.isEmpty())
            return refuse(tr("line %1: no serial number").arg(number));
        if (csv.m_rows.contains(serial))
            return refuse(tr("line %1: serial number \"%2\" is already on line %3")
                              .arg(QString::number(number), DisplayText::escaped(serial.left(80)),
                                   QString::number(csv.m_lines.value(serial))));
        csv.m_rows.insert(serial, fields.mid(1));
        csv.m_lines.insert(serial, number);
    }
    if (header)
        return refuse(tr("the CSV file is empty; it needs a header \"serial,<parameter>,...\""));
    if (error)
        error->clear();
    return csv;
}

std::optional<UnitValuesCsv> UnitValuesCsv::load(const QString& path, QString* error)
{
    QByteArray data;
    if (InputFile::read(path, kMaxFileBytes, &data, error) == InputFile::Status::CannotOpen)
        return std::nullopt;
    // A file over the cap is refused by parse(), which sees the extra byte.
    std::optional<UnitValuesCsv> csv = parse(data, error);
    if (!csv && error)
        *error = tr("%1: %2").arg(path, *error);
    return csv;
}

QStringList UnitValuesCsv::serials() const
{
    QStringList list = m_rows.keys();
    std::sort(list.begin(), list.end(), [this](const QString& a, const QString& b) {
        return m_lines.value(a) < m_lines.value(b);
    });
    return list;
}

int UnitValuesCsv::columnOf(const Recipe& recipe, int machineNumber, const QString& parameter) const
{
    const int qualified =
        int(m_columns.indexOf(QStringLiteral("%1:%2").arg(machineNumber).arg(parameter)));
    if (qualified >= 0)
        return qualified;
    const int plain = int(m_columns.indexOf(parameter));
    if (plain < 0)
        return -1;
    int holders = 0;
    for (const RecipePosition& p : recipe.positions) {
        for (const RecipeUnitValue& u : p.unitValues)
            holders += u.source == RecipeUnitValue::Source::Csv && u.name == parameter ? 1 : 0;
    }
    return holders == 1 ? plain : -2;
}

std::optional<QVector<UnitValuesCsv::Value>>
UnitValuesCsv::valuesFor(const Recipe& recipe, const ProfileRegistry& registry,
                         const QString& serial, QString* error) const
{
    auto refuse = [&](const QString& message) -> std::optional<QVector<Value>> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QString key = serial.trimmed();
    if (!m_rows.contains(key))
        return refuse(
            tr("serial number \"%1\" is not in the CSV file").arg(DisplayText::escaped(key)));
    const QStringList& cells = m_rows.value(key);
    const int line = m_lines.value(key);
    const RecipeChecker checker(registry);
    QVector<Value> values;
    for (int i = 0; i < recipe.positions.size(); ++i) {
        const RecipePosition& p = recipe.positions.at(i);
        const QString where = Recipe::positionText(i, p.machineNumber);
        for (const RecipeUnitValue& u : p.unitValues) {
            if (u.source != RecipeUnitValue::Source::Csv)
                continue;
            const int column = columnOf(recipe, p.machineNumber, u.name);
            if (column == -2)
                return refuse(tr("%1: column \"%2\" is ambiguous, several positions have this "
                                 "per-unit value; name the column \"%3:%2\"")
                                  .arg(where, u.name, QString::number(p.machineNumber)));
            if (column < 0)
                return refuse(tr("%1: the CSV file has no column \"%2\" (or \"%3:%2\") for this "
                                 "per-unit value")
                                  .arg(where, u.name, QString::number(p.machineNumber)));
            const QString cell = cells.value(column);
            if (cell.isEmpty())
                return refuse(tr("line %1, column \"%2\": no value for serial number \"%3\"")
                                  .arg(line)
                                  .arg(DisplayText::escaped(m_columns.at(column)),
                                       DisplayText::escaped(key)));
            bool ok = false;
            double v = QLocale::c().toDouble(cell, &ok);
            if (!ok && m_separator == QLatin1Char(';'))
                v = QLocale::c().toDouble(QString(cell).replace(QLatin1Char(','), QLatin1Char('.')),
                                          &ok);
            if (!ok || !std::isfinite(v))
                return refuse(tr("line %1, column \"%2\": \"%3\" is not a number")
                                  .arg(line)
                                  .arg(DisplayText::escaped(m_columns.at(column)),
                                       DisplayText::escaped(cell.left(40))));
            const QString problem = checker.checkUnitValue(recipe, p.machineNumber, u.name, v);
            if (!problem.isEmpty())
                return refuse(tr("line %1: %2").arg(QString::number(line), problem));
            values << Value{p.machineNumber, u.name, v};
        }
    }
    if (error)
        error->clear();
    return values;
}

} // namespace opentop
