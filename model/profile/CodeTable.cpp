#include "model/profile/CodeTable.h"

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

QString CodeEntry::explained() const
{
    const QString what = panel.isEmpty() ? name : panel + QLatin1Char(' ') + name;
    QString text =
        cause.isEmpty()
            ? what
            : QCoreApplication::translate("opentop::CodeEntry", "%1: %2").arg(what, cause);
    if (!remedy.isEmpty()) {
        // Remedies are lists ("A; B"): the message ends it as a sentence.
        const QString ends = QStringLiteral(".!?\u3002\uFF01\uFF1F");
        text += QLatin1Char(' ') +
                QCoreApplication::translate("opentop::CodeEntry", "What to do: %1").arg(remedy);
        if (!ends.contains(text.back()))
            text += QLatin1Char('.');
    }
    return text;
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
