#pragma once

#include <QCoreApplication>
#include <QHash>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

class ProfileRegistry;
class Recipe;

// Per-unit values from a CSV file keyed by serial number (docs/recipe-format.md): a header row
// "serial,<column>,...", where a column names a per-unit value of the recipe by its parameter
// name ("spno3.speed") or, when several positions have it, by machine number and name
// ("5:spno3.speed"); then one row per unit. Parsing is hardened: a byte-order mark, CRLF,
// quoted fields and ';' as the separator (with a decimal comma) are read; a row with the wrong
// number of fields, an empty or repeated serial, a repeated column or an oversized file are
// refused with the line. Values are checked against the recipe when they are looked up.
class UnitValuesCsv
{
    Q_DECLARE_TR_FUNCTIONS(opentop::UnitValuesCsv)
public:
    static constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024;
    static constexpr int kMaxColumns = 1000;

    struct Value
    {
        int machineNumber = 0;
        QString parameter;
        double value = 0;
    };

    static std::optional<UnitValuesCsv> parse(const QByteArray& data, QString* error);
    static std::optional<UnitValuesCsv> load(const QString& path, QString* error);

    QStringList columns() const { return m_columns; }
    int rows() const { return int(m_rows.size()); }
    QStringList serials() const; // in file order
    bool contains(const QString& serial) const { return m_rows.contains(serial.trimmed()); }

    // Every per-unit value of `recipe` whose source is the CSV, for the unit `serial`, each
    // within the recipe's range and allowed by the drive (RecipeChecker::checkUnitValue).
    std::optional<QVector<Value>> valuesFor(const Recipe& recipe, const ProfileRegistry& registry,
                                            const QString& serial, QString* error) const;

private:
    // The column that holds the per-unit value `parameter` of position `machineNumber`; -1
    // when there is none, -2 when a plain name is ambiguous for this recipe.
    int columnOf(const Recipe& recipe, int machineNumber, const QString& parameter) const;

    QChar m_separator = QLatin1Char(',');
    QStringList m_columns; // after "serial"
    QHash<QString, QStringList> m_rows;
    QHash<QString, int> m_lines; // serial -> line number in the file
};

} // namespace opentop
