// libFuzzer harness: the per-unit values CSV reader (UnitValuesCsv::parse) on arbitrary bytes,
// then, for what it accepts, the values of a few serial numbers looked up for two recipes
// (UnitValuesCsv::valuesFor): one whose positions share a per-unit value, so that plain column
// names are ambiguous, and one with a single position. Any crash, leak or sanitizer report is a
// defect; a refusal with a reason is the expected outcome, and a value handed out must be
// within its recipe's range.
#include "model/eol/Recipe.h"
#include "model/eol/UnitValuesCsv.h"
#include "model/profile/ProfileRegistry.h"
#include <QByteArray>
#include <QSet>
#include <QString>
#include <cmath>
#include <cstddef>
#include <cstdint>

using namespace opentop;

namespace {

RecipeUnitValue csvValue(const char* name, double min, double max)
{
    RecipeUnitValue u;
    u.name = QString::fromLatin1(name);
    u.min = min;
    u.max = max;
    u.source = RecipeUnitValue::Source::Csv;
    return u;
}

RecipePosition position(int machineNumber, const char* family, QVector<RecipeUnitValue> values)
{
    RecipePosition p;
    p.machineNumber = machineNumber;
    p.family = QString::fromLatin1(family);
    p.unitValues = std::move(values);
    return p;
}

// Two DBUs with the same per-unit speed (columns "1:spno3.speed" and "5:spno3.speed"), one of
// them also with a deceleration time whose allowed values have a gap, and a DC PID controller.
Recipe sharedRecipe()
{
    RecipeUnitValue typed = csvValue("spno4.speed", 250, 3000);
    typed.source = RecipeUnitValue::Source::Operator; // not read from the file
    Recipe recipe;
    recipe.positions << position(1, "dbu",
                                 {csvValue("spno3.speed", 1400, 1600),
                                  csvValue("spno3.decel", 0.5, 30), typed})
                     << position(5, "dbu", {csvValue("spno3.speed", 250, 3000)})
                     << position(7, "dcpid", {csvValue("pid.p", 0, 100)});
    recipe.positions[1].variants << QStringLiteral("dbu400");
    return recipe;
}

Recipe singleRecipe()
{
    Recipe recipe;
    recipe.positions << position(1, "dbu", {csvValue("spno3.speed", 1400, 1600)});
    return recipe;
}

void lookUp(const UnitValuesCsv& csv, const Recipe& recipe, const QString& serial)
{
    QString error;
    const auto values = csv.valuesFor(recipe, ProfileRegistry::builtIn(), serial, &error);
    if (!values) {
        if (error.isEmpty())
            __builtin_trap(); // a refusal must say why
        return;
    }
    for (const UnitValuesCsv::Value& v : *values) {
        const RecipePosition* p = recipe.position(v.machineNumber);
        if (!p || !std::isfinite(v.value))
            __builtin_trap();
        bool inRange = false;
        for (const RecipeUnitValue& u : p->unitValues)
            inRange = inRange || (u.name == v.parameter && v.value >= u.min && v.value <= u.max);
        if (!inRange)
            __builtin_trap();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static const Recipe shared = sharedRecipe();
    static const Recipe single = singleRecipe();
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    QString error;
    const std::optional<UnitValuesCsv> csv = UnitValuesCsv::parse(bytes, &error);
    if (!csv) {
        if (error.isEmpty())
            __builtin_trap();
        return 0;
    }
    // what was accepted: named columns, one row per distinct non-empty serial number
    const QStringList serials = csv->serials();
    if (csv->columns().isEmpty() || serials.size() != csv->rows() ||
        QSet<QString>(serials.begin(), serials.end()).size() != serials.size())
        __builtin_trap();
    for (const QString& column : csv->columns())
        if (column.isEmpty())
            __builtin_trap();
    for (int i = 0; i < serials.size() && i < 8; ++i) {
        if (serials.at(i).isEmpty() || !csv->contains(serials.at(i)))
            __builtin_trap();
        lookUp(*csv, shared, serials.at(i));
        lookUp(*csv, single, serials.at(i));
    }
    lookUp(*csv, shared, QStringLiteral("not-in-the-file"));
    return 0;
}
