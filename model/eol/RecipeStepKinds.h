#pragma once

#include "model/eol/RecipeTypes.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

class Profile;

// The one table of recipe step types: each type's file name, its title, and the fields its
// JSON object holds (with what kind of value, its unit and range, and what an empty optional
// field means). The parser takes its allowed keys from here, Recipe its names and titles, the
// recipe editor its list, titles and form, `eol recipe show` its titles; a new step type is one
// entry here plus its runner in EolStepRunner (RecipeStepKindsTest fails for a type without
// an entry).
class RecipeStepKinds
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RecipeStepKinds)
public:
    struct Field
    {
        enum class Kind
        {
            Number,    // a number in `unit`
            Integer,   // a whole number from min to max
            Direction, // "cw" or "ccw"
            Unit,      // the unit the step's numbers are given in (checked against the profile)
            Parameter, // a parameter's name
            Text,      // free text
            Limits     // a list of measured limits
        };
        const char* key;
        Kind kind;
        bool required;
        const char* label; // for the editor's form (translated in this class's context)
        const char* unit;  // "s", or "" for the speed's or the value's own unit
        const char* empty; // what an empty optional field means, for the editor
        double min = 0;    // Integer: the range
        double max = 0;
    };
    struct Kind
    {
        RecipeStep::Type type;
        const char* name;  // in recipe files: "waitSpeed"
        const char* title; // in records and lists: "wait for speed" (translated)
        QVector<Field> fields;
    };

    static const QVector<Kind>& all();
    static const Kind* of(RecipeStep::Type type);
    static const Kind* of(const QString& name);
    static QString title(RecipeStep::Type type);
    // The JSON keys a step of `type` may hold: "type" and its fields' keys.
    static QStringList keys(RecipeStep::Type type);
    // What a step does beyond its title, from its JSON as a file or the editor holds it (a
    // step being edited may be incomplete): "1500 ± 50 r/min within 5 s"; empty for a step
    // without fields. `profile` names parameters by their labels (none: by their names).
    static QString summary(const QJsonObject& step, const Profile* profile = nullptr);
    // Title and summary on one line: "wait for speed: 1500 ± 50 r/min within 5 s".
    static QString line(const QJsonObject& step, const Profile* profile = nullptr);
    static QString fieldLabel(const Field& field);
    static QString fieldEmpty(const Field& field);
};

} // namespace opentop
