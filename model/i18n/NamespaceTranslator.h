#pragma once

#include <QTranslator>

namespace opentop {

// The program's translator. lupdate files a message under the class whose member says tr(), and
// a free function's under its namespace ("opentop"); at run time the files' own tr() helpers
// ask with their class ("opentop::AlarmsCommand"). A message not found under its class is looked
// up under the namespace, so both kinds reach their translation.
class NamespaceTranslator : public QTranslator
{
    Q_OBJECT
public:
    using QTranslator::QTranslator;

    QString translate(const char* context, const char* sourceText,
                      const char* disambiguation = nullptr, int n = -1) const override;
};

} // namespace opentop
