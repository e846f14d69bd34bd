#include "model/eol/ShiftPlan.h"

#include <QStringList>
#include <algorithm>

namespace opentop {

ShiftPlan::ShiftPlan()
    : ShiftPlan({QTime(6, 0), QTime(14, 0), QTime(22, 0)}, QTimeZone::systemTimeZone())
{
}

ShiftPlan::ShiftPlan(QVector<QTime> boundaries, QTimeZone zone)
    : boundaries_(std::move(boundaries))
    , zone_(std::move(zone))
{
    std::sort(boundaries_.begin(), boundaries_.end());
    if (boundaries_.isEmpty())
        boundaries_.append(QTime(0, 0));
}

std::optional<ShiftPlan> ShiftPlan::parse(const QString& text, const QTimeZone& zone,
                                          QString* error)
{
    QVector<QTime> times;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QTime t = QTime::fromString(part.trimmed(), QStringLiteral("H:mm"));
        if (!t.isValid()) {
            if (error)
                *error = tr("\"%1\" is not a time of day such as 06:00").arg(part.trimmed());
            return std::nullopt;
        }
        if (!times.isEmpty() && t <= times.constLast()) {
            if (error)
                *error = tr("shift starts must be in order from the day's first: %1").arg(text);
            return std::nullopt;
        }
        times.append(t);
    }
    if (times.isEmpty()) {
        if (error)
            *error = tr("no shift start given; e.g. 06:00,14:00,22:00");
        return std::nullopt;
    }
    return ShiftPlan(times, zone);
}

QDateTime ShiftPlan::shiftStart(const QDateTime& time) const
{
    const QDateTime local = time.toTimeZone(zone_);
    const QTime clock = local.time();
    QDate day = local.date();
    const QTime* start = nullptr;
    for (const QTime& b : boundaries_)
        if (b <= clock)
            start = &b;
    if (!start) { // before the day's first boundary: the previous day's last shift
        day = day.addDays(-1);
        start = &boundaries_.constLast();
    }
    return QDateTime(day, *start, zone_);
}

QString ShiftPlan::shiftName(const QDateTime& time) const
{
    return shiftStart(time).toString(QStringLiteral("yyyy-MM-dd HH:mm"));
}

} // namespace opentop
