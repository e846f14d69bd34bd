#include "profile/CodeTable.h"

#include <QCoreApplication>

namespace opentop {

QString CodeEntry::clearedByText(const QString& reset)
{
    if (reset == QLatin1String("alarm-reset"))
        return QCoreApplication::translate("opentop::CodeEntry", "Alarm-Reset");
    if (reset == QLatin1String("power"))
        return QCoreApplication::translate("opentop::CodeEntry", "power cycle");
    if (reset == QLatin1String("auto"))
        return QCoreApplication::translate("opentop::CodeEntry", "by itself");
    return QCoreApplication::translate("opentop::CodeEntry", "—");
}

const CodeEntry* CodeTable::find(qint64 code) const
{
    for (const CodeEntry& e : entries) {
        if (e.code == code)
            return &e;
    }
    return nullptr;
}

} // namespace opentop
