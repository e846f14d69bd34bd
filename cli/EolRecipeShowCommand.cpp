#include "cli/EolRecipeShowCommand.h"

#include "cli/CliContext.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "cli/FileCommandSupport.h"
#include "cli/TextTable.h"
#include "model/eol/CertificateHtml.h"
#include "model/eol/RecipeFile.h"
#include "model/eol/RecipeStepKinds.h"
#include "model/eol/SerialRule.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolRecipeShowCommand", text);
}

QString listOr(const QStringList& list, const QString& none)
{
    return list.isEmpty() ? none : list.join(QStringLiteral(", "));
}

// The unit a setting's number is in: the recipe's own, else the profile's.
QString unitOf(const Profile* profile, const RecipePosition& position, const RecipeSetting& s)
{
    if (!s.unit.isEmpty() || !s.value.isDouble() || !profile)
        return s.unit;
    const ParameterMeta* meta = profile->parameter(s.name);
    if (!meta)
        return QString();
    return meta->specFor(RecipeChecker::contextOf(*profile, position, position.variants.value(0)))
        .unit;
}

QString unitOfValue(const Profile* profile, const RecipePosition& position,
                    const RecipeUnitValue& v)
{
    if (!v.unit.isEmpty() || !profile)
        return v.unit;
    const ParameterMeta* meta = profile->parameter(v.name);
    return meta ? meta->specFor(
                          RecipeChecker::contextOf(*profile, position, position.variants.value(0)))
                      .unit
                : QString();
}

} // namespace

QString EolRecipeShowCommand::summary() const
{
    return tr("Show a recipe: positions, settings by label with units, steps and limits");
}

QString EolRecipeShowCommand::limitText(const Profile* profile, const RecipeLimit& limit)
{
    Measurement m;
    m.lower = limit.lower;
    m.upper = limit.upper;
    m.unit = limit.unit;
    const QString what =
        limit.statistic == QLatin1String("value")
            ? tr("'%1'").arg(EolSupport::label(profile, limit.parameter))
            : tr("'%1' %2").arg(EolSupport::label(profile, limit.parameter), limit.statistic);
    return tr("%1: %2").arg(what, CertificateHtml::limitsText(m));
}

void EolRecipeShowCommand::printPosition(CliContext& context, const Recipe& recipe, int index)
{
    QTextStream& out = context.out();
    const RecipePosition& position = recipe.positions.at(index);
    const Profile* profile = ProfileRegistry::builtIn().family(position.family);
    out << '\n'
        << Recipe::positionText(index, position.machineNumber)
        << (position.name.isEmpty() ? QString()
                                    : QStringLiteral(": ") + DisplayText::escaped(position.name))
        << '\n';
    if (position.settings.isEmpty()) {
        out << tr("  no settings") << '\n';
    } else {
        TextTable settings({tr("  setting"), tr("value"), tr("unit")});
        for (const RecipeSetting& s : position.settings) {
            const QString value =
                s.value.isDouble() ? EolSupport::number(s.value.toDouble()) : s.value.toString();
            settings.addRow({QStringLiteral("  ") + EolSupport::label(profile, s.name), value,
                             unitOf(profile, position, s)});
        }
        settings.print(out);
    }
    if (!position.unitValues.isEmpty()) {
        TextTable values({tr("  per-unit value"), tr("range"), tr("from")});
        for (const RecipeUnitValue& v : position.unitValues) {
            const QString range = EolSupport::withUnit(
                tr("%1 … %2").arg(EolSupport::number(v.min), EolSupport::number(v.max)),
                unitOfValue(profile, position, v));
            values.addRow({QStringLiteral("  ") + EolSupport::label(profile, v.name), range,
                           v.source == RecipeUnitValue::Source::Csv ? tr("CSV file by serial")
                                                                    : tr("typed by the operator")});
        }
        values.print(out);
    }
    if (position.steps.isEmpty()) {
        out << tr("  no test steps") << '\n';
        return;
    }
    out << tr("  steps:") << '\n';
    // The steps as the file has them, described by the step table (RecipeStepKinds).
    const QJsonArray steps = RecipeFile::toObject(recipe)
                                 .value(QStringLiteral("positions"))
                                 .toArray()
                                 .at(index)
                                 .toObject()
                                 .value(QStringLiteral("steps"))
                                 .toArray();
    for (int i = 0; i < position.steps.size(); ++i) {
        const RecipeStep& step = position.steps.at(i);
        out << QStringLiteral("  %1. %2\n")
                   .arg(i + 1)
                   .arg(DisplayText::escaped(
                       RecipeStepKinds::line(steps.at(i).toObject(), profile)));
        if (step.type == RecipeStep::Type::Read && !step.equals.isEmpty())
            continue;
        for (const RecipeLimit& l : step.limits)
            out << QStringLiteral("       %1\n").arg(DisplayText::escaped(limitText(profile, l)));
    }
}

int EolRecipeShowCommand::run(CliContext& context, const QStringList& args)
{
    int code = ExitOk;
    const std::optional<EolSupport::LoadedRecipe> loaded =
        EolSupport::recipeArgument(context, args, synopsis(), false, &code);
    if (!loaded)
        return code;
    const QString path = args.first();
    const Recipe& recipe = loaded->recipe;
    if (context.json()) {
        // The recipe as its file holds it, with the labels the profiles give its parameters.
        QJsonObject labels;
        for (const RecipePosition& p : recipe.positions) {
            const Profile* profile = ProfileRegistry::builtIn().family(p.family);
            auto add = [&](const QString& name) {
                if (!name.isEmpty())
                    labels.insert(name, EolSupport::label(profile, name));
            };
            for (const RecipeSetting& s : p.settings)
                add(s.name);
            for (const RecipeUnitValue& v : p.unitValues)
                add(v.name);
            for (const RecipeStep& s : p.steps) {
                for (const RecipeLimit& l : s.limits)
                    add(l.parameter);
            }
        }
        FileCommandSupport::printJson(
            context, {{QStringLiteral("command"), QStringLiteral("eol recipe show")},
                      {QStringLiteral("file"), path},
                      {QStringLiteral("checksum"), loaded->checksum},
                      {QStringLiteral("recipe"), RecipeFile::toObject(recipe)},
                      {QStringLiteral("labels"), labels}});
        return ExitOk;
    }
    QTextStream& out = context.out();
    // Every text of the file is shown escaped (issue 28): tables through TextTable, lines here.
    out << tr("%1, revision %2")
               .arg(DisplayText::escaped(recipe.product), DisplayText::escaped(recipe.revision))
        << '\n';
    if (!recipe.description.isEmpty())
        out << DisplayText::escapedLines(recipe.description) << '\n';
    // The pattern is checked text (SerialRule: no control characters), shown as it is.
    out << tr("serial numbers: %1").arg(SerialRule::patternText(recipe)) << '\n';
    out << tr("checksum %1").arg(loaded->checksum) << "\n\n";
    TextTable positions({tr("position"), tr("machine number"), tr("name"), tr("family"),
                         tr("variants"), tr("firmware")});
    for (int i = 0; i < recipe.positions.size(); ++i) {
        const RecipePosition& p = recipe.positions.at(i);
        const Profile* profile = ProfileRegistry::builtIn().family(p.family);
        QStringList variants;
        for (const QString& v : p.variants) {
            const ProfileVariant* variant = profile ? profile->variant(v) : nullptr;
            variants << (variant && !variant->model.isEmpty() ? variant->model : v);
        }
        positions.addRow({QString::number(i + 1), QString::number(p.machineNumber), p.name,
                          profile && !profile->name.isEmpty() ? profile->name : p.family,
                          listOr(variants, tr("any")), listOr(p.firmware, tr("any"))});
    }
    positions.setRightAligned(0);
    positions.setRightAligned(1);
    positions.print(out);
    for (int i = 0; i < recipe.positions.size(); ++i)
        printPosition(context, recipe, i);
    out.flush();
    return ExitOk;
}

} // namespace opentop
