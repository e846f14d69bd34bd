#include "model/i18n/NamespaceTranslator.h"

#include <cstring>

namespace opentop {

QString NamespaceTranslator::translate(const char* context, const char* sourceText,
                                       const char* disambiguation, int n) const
{
    const QString found = QTranslator::translate(context, sourceText, disambiguation, n);
    if (!found.isNull() || !context)
        return found;
    const char* scope = std::strstr(context, "::");
    if (!scope || std::strstr(scope + 2, "::"))
        return found; // not a class of one namespace
    const QByteArray ns(context, int(scope - context));
    return QTranslator::translate(ns.constData(), sourceText, disambiguation, n);
}

} // namespace opentop
