#pragma once

#include "model/eol/Recipe.h"

#include <QCoreApplication>
#include <QHash>
#include <memory>
#include <optional>

namespace opentop {

class UnitValuesCsv;

// The recipe a station runs and where each unit's own values come from: the recipe file
// (loaded only when the checker passes it, with its checksum, which approvals name) and the
// per-unit values, typed by the operator or looked up by serial in the recipe's CSV file.
class StationRecipe
{
    Q_DECLARE_TR_FUNCTIONS(opentop::StationRecipe)
public:
    StationRecipe();
    ~StationRecipe();

    // False with every checker problem; the recipe stays as it was.
    bool load(const QString& path, QStringList* problems);
    bool loadUnitValues(const QString& path, QString* error);
    bool has() const { return m_has; }
    const Recipe& recipe() const { return m_recipe; }
    QString path() const { return m_path; }
    QString checksum() const { return m_checksum; }
    bool hasUnitValues() const { return bool(m_csv); }
    // The values the operator types for each unit (the recipe's "operator" ones).
    QVector<QPair<int, RecipeUnitValue>> operatorValues() const;
    // One unit's values: what the operator typed and, for the CSV ones, the row of `serial`;
    // nullopt with *error (naming the file, line or column) when one is missing or not allowed.
    std::optional<QHash<int, QHash<QString, double>>>
    unitValues(const QString& serial, const QHash<int, QHash<QString, double>>& typed,
               QString* error) const;

private:
    Recipe m_recipe;
    bool m_has = false;
    QString m_path;
    QString m_checksum;
    std::unique_ptr<UnitValuesCsv> m_csv;
};

} // namespace opentop
