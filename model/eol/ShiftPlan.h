#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QTime>
#include <QTimeZone>
#include <QVector>
#include <optional>

namespace opentop {

// A factory's shifts: the clock times at which one shift ends and the next begins, in the
// factory's time zone (e.g. 06:00, 14:00, 22:00). A shift runs from its boundary to the next;
// the last one of a day runs past midnight, so 02:00 belongs to the shift that began at 22:00
// the day before.
class ShiftPlan
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ShiftPlan)
public:
    ShiftPlan(); // 06:00, 14:00, 22:00 in the system's time zone
    ShiftPlan(QVector<QTime> boundaries, QTimeZone zone);

    // "06:00,14:00,22:00"; refuses an empty, unordered or unreadable list.
    static std::optional<ShiftPlan> parse(const QString& text, const QTimeZone& zone,
                                          QString* error);

    // When the shift that `time` falls into began (in the plan's zone).
    QDateTime shiftStart(const QDateTime& time) const;
    // "2026-11-24 22:00": the shift's date and start, the name the reports use.
    QString shiftName(const QDateTime& time) const;
    const QVector<QTime>& boundaries() const { return boundaries_; }

private:
    QVector<QTime> boundaries_; // ascending
    QTimeZone zone_;
};

} // namespace opentop
