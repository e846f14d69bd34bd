#pragma once

// Shared by the recipe tests: the example recipes of docs/examples and a way to see a
// checker's problems.

#include "model/eol/RecipeChecker.h"
#include "model/eol/RecipeFile.h"
#include "model/profile/ProfileRegistry.h"

#include <QString>
#include <gtest/gtest.h>

namespace opentop::test {

inline QString exampleRecipePath(const char* name)
{
    return QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/") + QString::fromLatin1(name);
}

inline Recipe exampleRecipe(const char* name)
{
    QString error;
    const std::optional<Recipe> recipe = RecipeFile::load(exampleRecipePath(name), &error);
    EXPECT_TRUE(recipe) << qPrintable(error);
    return recipe.value_or(Recipe());
}

inline QVector<RecipeProblem> problemsOf(const Recipe& recipe)
{
    return RecipeChecker(ProfileRegistry::builtIn()).check(recipe);
}

inline QString textOf(const QVector<RecipeProblem>& problems)
{
    QStringList lines;
    for (const RecipeProblem& p : problems)
        lines << p.path + QStringLiteral(" | ") + p.message;
    return lines.join(QLatin1Char('\n'));
}

} // namespace opentop::test
