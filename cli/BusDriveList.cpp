#include "cli/BusDriveList.h"

#include <QLocale>

namespace opentop {

QString BusDriveList::ageText(const QDateTime& then, const QDateTime& now)
{
    const qint64 s = std::max<qint64>(0, then.secsTo(now));
    if (s < 60)
        return tr("%1 s ago").arg(s); // abbreviated units take no plural
    if (s < 3600)
        return tr("%1 min ago").arg(s / 60);
    if (s < 48 * 3600)
        return tr("%1 h ago").arg(s / 3600);
    return tr("%n day(s) ago", nullptr, int(s / 86400));
}

QString BusDriveList::sourceText(const QDateTime& now) const
{
    switch (source) {
    case Source::Option:
        return QStringLiteral("--bus-drives");
    case Source::Environment:
        return QStringLiteral("OPENTOP_BUS_DRIVES");
    case Source::Simulated:
        return tr("the simulated bus's drives");
    case Source::Remembered:
        if (!savedAt.isValid())
            return tr("the drives last seen on %1").arg(place);
        return tr("the drives the last scan of %1 found (%2, %3)")
            .arg(place,
                 QLocale().toString(savedAt.toLocalTime(), QStringLiteral("yyyy-MM-dd HH:mm")),
                 ageText(savedAt, now));
    case Source::None:
        break;
    }
    return tr("no list of the drives on the bus");
}

} // namespace opentop
