#pragma once

#include "model/eol/RecipeTypes.h"

#include <QCoreApplication>
#include <QString>
#include <QVector>
#include <optional>

namespace opentop {

// An end-of-line recipe: what one product's drives must be, hold and do to pass
// (docs/recipe-format.md). Read and written by RecipeFile, validated by RecipeChecker.
class Recipe
{
    Q_DECLARE_TR_FUNCTIONS(opentop::Recipe)
public:
    QString product;  // "Conveyor C-200"
    QString revision; // "B"
    QString description;
    // The product's serial numbers (SerialRule): a regular expression the whole serial must
    // match, "" for any; and one serial it matches, shown when a serial is refused. Absent from
    // a file when empty, so that older recipes keep their checksums.
    QString serialPattern;             // "^TR[0-9]{8}$"
    QString serialExample;             // "TR00012345"
    QVector<RecipePosition> positions; // in fixture order
    RecipeRetest retest;               // absent from a file: the defaults

    const RecipePosition* position(int machineNumber) const;

    // The step type's name in the file ("waitSpeed") and back.
    static QString stepTypeName(RecipeStep::Type type);
    static std::optional<RecipeStep::Type> stepTypeFromName(const QString& name);
    static QStringList stepTypeNames();
    // The step in words for people: "wait for speed".
    static QString stepTitle(RecipeStep::Type type);
    static QString sourceName(RecipeUnitValue::Source source);
    static QString passedName(RecipeRetest::Passed passed); // "technician", "refuse", "allow"
    static std::optional<RecipeRetest::Passed> passedFromName(const QString& name);
    static std::optional<RecipeUnitValue::Source> sourceFromName(const QString& name);
    // What a hold or read step may measure of a parameter.
    static QStringList statistics();

    // "position 2 (machine number 5)", the way every message names a drive of the recipe
    // (positions count from 1).
    static QString positionText(int index, int machineNumber);
};

} // namespace opentop
