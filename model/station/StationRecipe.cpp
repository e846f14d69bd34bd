#include "model/station/StationRecipe.h"

#include "model/eol/RecipeChecker.h"
#include "model/eol/RecipeFile.h"
#include "model/eol/UnitValuesCsv.h"
#include "model/profile/ProfileRegistry.h"

namespace opentop {

StationRecipe::StationRecipe() = default;
StationRecipe::~StationRecipe() = default;

bool StationRecipe::load(const QString& path, QStringList* problems)
{
    QString error;
    QString checksum;
    const std::optional<Recipe> recipe = RecipeFile::load(path, &error, &checksum);
    if (!recipe) {
        *problems = {error};
        return false;
    }
    const QVector<RecipeProblem> found = RecipeChecker(ProfileRegistry::builtIn()).check(*recipe);
    if (!found.isEmpty()) {
        problems->clear();
        for (const RecipeProblem& p : found)
            *problems << p.message;
        return false;
    }
    m_recipe = *recipe;
    m_checksum = checksum;
    m_path = path;
    m_has = true;
    m_csv.reset(); // another recipe's values
    return true;
}

bool StationRecipe::loadUnitValues(const QString& path, QString* error)
{
    std::optional<UnitValuesCsv> csv = UnitValuesCsv::load(path, error);
    if (!csv)
        return false;
    m_csv = std::make_unique<UnitValuesCsv>(std::move(*csv));
    return true;
}

QVector<QPair<int, RecipeUnitValue>> StationRecipe::operatorValues() const
{
    QVector<QPair<int, RecipeUnitValue>> values;
    for (const RecipePosition& p : m_recipe.positions)
        for (const RecipeUnitValue& u : p.unitValues)
            if (u.source == RecipeUnitValue::Source::Operator)
                values.append({p.machineNumber, u});
    return values;
}

std::optional<QHash<int, QHash<QString, double>>>
StationRecipe::unitValues(const QString& serial, const QHash<int, QHash<QString, double>>& typed,
                          QString* error) const
{
    QHash<int, QHash<QString, double>> values = typed;
    bool needsCsv = false;
    for (const RecipePosition& p : m_recipe.positions)
        for (const RecipeUnitValue& u : p.unitValues)
            needsCsv = needsCsv || u.source == RecipeUnitValue::Source::Csv;
    if (!needsCsv)
        return values;
    if (!m_csv) {
        *error = tr("this recipe takes per-unit values from a CSV file: open it first");
        return std::nullopt;
    }
    const auto fromCsv = m_csv->valuesFor(m_recipe, ProfileRegistry::builtIn(), serial, error);
    if (!fromCsv)
        return std::nullopt;
    for (const UnitValuesCsv::Value& v : *fromCsv)
        values[v.machineNumber][v.parameter] = v.value;
    return values;
}

} // namespace opentop
