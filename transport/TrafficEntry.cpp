#include "transport/TrafficEntry.h"

#include "transport/RtuFrame.h"

#include <QCoreApplication>

namespace opentop {

QString TrafficEntry::directionText() const
{
    switch (direction) {
    case Direction::Tx:
        return QCoreApplication::translate("opentop::Transport", "TX");
    case Direction::Rx:
        return QCoreApplication::translate("opentop::Transport", "RX");
    case Direction::Event:
        return QCoreApplication::translate("opentop::Transport", "--");
    }
    return QString();
}

QString TrafficEntry::toLine() const
{
    // "12:00:01.234 TX #1 01 03 CA 03 00 01 4B D2  read 03 0xCA03 ×1"
    QString line = time.isValid() ? time.toString(QStringLiteral("HH:mm:ss.zzz"))
                                  : QStringLiteral("--:--:--.---");
    line += QLatin1Char(' ') + directionText();
    line += QStringLiteral(" #%1").arg(slave);
    if (!bytes.isEmpty())
        line += QLatin1Char(' ') + RtuFrame::toHex(bytes);
    if (!summary.isEmpty())
        line += QStringLiteral("  ") + summary;
    if (responseMs >= 0)
        line += QStringLiteral(" (%1 ms)").arg(responseMs, 0, 'f', 1);
    if (!error.isEmpty())
        line += QStringLiteral("  ") +
                QCoreApplication::translate("opentop::Transport", "error: %1").arg(error);
    return line;
}

} // namespace opentop
