#include "eol/YieldReport.h"

#include <QSet>
#include <algorithm>
#include <map>

namespace opentop {

namespace {

QVector<YieldRow> grouped(QVector<UnitRecord> units, const ShiftPlan* plan,
                          const YieldReport::Earlier& earlier)
{
    std::stable_sort(units.begin(), units.end(), [](const UnitRecord& a, const UnitRecord& b) {
        return a.started < b.started;
    });
    std::map<std::pair<QString, QString>, YieldRow> rows;
    QSet<QPair<QString, QString>> seen = earlier; // (recipe, serial) whose first record is past
    for (const UnitRecord& u : units) {
        const QString shift = plan ? plan->shiftName(u.started) : QString();
        YieldRow& row = rows[{u.recipeName, shift}];
        row.recipe = u.recipeName;
        row.shift = shift;
        ++row.records;
        if (u.status == UnitStatus::Running || u.status == UnitStatus::Interrupted)
            ++row.running;
        if (!u.isPass())
            ++row.failureReasons[YieldReport::reasonOf(u)];
        const QPair<QString, QString> key{u.recipeName, u.serial};
        if (seen.contains(key))
            continue;
        seen.insert(key);
        ++row.serials;
        if (u.isPass())
            ++row.firstPass;
    }
    QVector<YieldRow> list;
    for (auto& entry : rows)
        list.append(entry.second);
    return list;
}

} // namespace

QString YieldReport::reasonOf(const UnitRecord& unit)
{
    if (!unit.failureReason.isEmpty())
        return unit.failureReason;
    switch (unit.status) {
    case UnitStatus::Running:
        return tr("still running (or its station has not restarted since it stopped)");
    case UnitStatus::Interrupted:
        return tr("interrupted");
    case UnitStatus::Aborted:
        return tr("aborted");
    case UnitStatus::Fail:
        return tr("failed, no reason recorded");
    case UnitStatus::Pass:
        break;
    }
    return QString();
}

QVector<YieldRow> YieldReport::perRecipe(const QVector<UnitRecord>& units, const Earlier& earlier)
{
    return grouped(units, nullptr, earlier);
}

QVector<YieldRow> YieldReport::perShift(const QVector<UnitRecord>& units, const ShiftPlan& plan,
                                        const Earlier& earlier)
{
    return grouped(units, &plan, earlier);
}

} // namespace opentop
