#include "ui/eol/RecipeNumberText.h"

#include <QLocale>

namespace opentop {

QString RecipeNumberText::text(const QJsonValue& value)
{
    if (value.isDouble())
        return QString::number(value.toDouble(), 'g', 10);
    return value.isString() ? value.toString() : QString();
}

QJsonValue RecipeNumberText::value(const QString& text)
{
    const QString t = text.trimmed();
    if (t.isEmpty())
        return QJsonValue(QJsonValue::Undefined);
    bool ok = false;
    double v = QLocale::c().toDouble(t, &ok);
    if (!ok)
        v = QLocale().toDouble(t, &ok);
    return ok ? QJsonValue(v) : QJsonValue(t);
}

} // namespace opentop
