#pragma once

#include <QJsonValue>
#include <QString>

namespace opentop {

// A recipe's numbers as the editor's fields show and take them: the file's notation shown, the
// user's or the file's taken; empty is a key left out; text that is not a number is kept as
// text, so that the recipe checker names it rather than the field dropping it silently.
class RecipeNumberText
{
public:
    static QString text(const QJsonValue& value);
    static QJsonValue value(const QString& text); // Undefined when empty
};

} // namespace opentop
