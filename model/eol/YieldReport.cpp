#include "model/eol/YieldReport.h"

#include "model/eol/ResultQueries.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace opentop {

namespace {

struct SerialState
{
    YieldRow* row = nullptr; // where its first verdict counted
    int verdicts = 0;
    bool passedBySecond = false;
};

QVector<YieldRow> grouped(QVector<UnitRecord> units, const ShiftPlan* plan,
                          const YieldReport::Earlier& earlier)
{
    std::stable_sort(units.begin(), units.end(), [](const UnitRecord& a, const UnitRecord& b) {
        return a.started < b.started;
    });
    using Key = std::tuple<QString, QString, QString, QString>; // name, revision, checksum, shift
    std::map<Key, YieldRow> rows;                               // stable addresses
    QHash<QPair<QString, QString>, SerialState> serials;
    for (const UnitRecord& u : units) {
        const QString shift = plan ? plan->shiftName(u.started) : QString();
        YieldRow& row = rows[{u.recipeName, u.recipeRevision, u.recipeChecksum, shift}];
        row.checksum = u.recipeChecksum;
        row.recipe = u.recipeName;
        row.revision = u.recipeRevision;
        row.shift = shift;
        ++row.records;
        switch (u.status) {
        case UnitStatus::Running:
        case UnitStatus::Interrupted:
            ++row.running;
            ++row.stationReasons[YieldReport::reasonOf(u)];
            break;
        case UnitStatus::Error:
        case UnitStatus::Aborted:
            ++row.stationErrors;
            ++row.stationReasons[YieldReport::reasonOf(u)];
            break;
        case UnitStatus::Fail:
            ++row.failed;
            ++row.failureReasons[YieldReport::reasonOf(u)];
            break;
        case UnitStatus::Pass:
            ++row.passed;
            break;
        }
        if (!u.hasVerdict())
            continue;
        ++row.verdicts;
        const QPair<QString, QString> key{u.recipeChecksum, u.serial};
        auto found = serials.find(key);
        if (found == serials.end()) {
            SerialState state;
            if (earlier.contains(key)) {
                state.verdicts = earlier.value(key).verdicts; // a retest: counted where it began
            } else {
                state.row = &row;
                ++row.serials;
                row.firstPass += u.isPass() ? 1 : 0;
            }
            found = serials.insert(key, state);
        }
        SerialState& state = found.value();
        ++state.verdicts;
        if (!state.row)
            continue;
        if (u.isPass() && state.verdicts <= 2 && !state.passedBySecond) {
            state.passedBySecond = true;
            ++state.row->secondPass;
        }
    }
    // The latest verdict decides the last pass (a pass then a fail is none): counted once all
    // are seen.
    QHash<QPair<QString, QString>, bool> latest;
    for (const UnitRecord& u : units)
        if (u.hasVerdict())
            latest[{u.recipeChecksum, u.serial}] = u.isPass();
    for (auto it = serials.cbegin(); it != serials.cend(); ++it)
        if (it->row && latest.value(it.key()))
            ++it->row->lastPass;
    QVector<YieldRow> list;
    for (auto& entry : rows)
        list.append(entry.second);
    return list;
}

} // namespace

QString YieldRow::title() const
{
    return revision.isEmpty() ? recipe : YieldReport::tr("%1 rev. %2").arg(recipe, revision);
}

QString YieldReport::percentText(double share)
{
    return tr("%1 %").arg(share * 100, 0, 'f', 1);
}

QString YieldReport::yieldText(const YieldRow& row)
{
    if (row.serials == 0)
        return tr("first-pass yield – (no serial tested yet)");
    return tr("first-pass yield %1 (%2 of %3 serials) · second-pass %4 · last-pass %5")
        .arg(percentText(row.firstPassYield()))
        .arg(row.firstPass)
        .arg(row.serials)
        .arg(percentText(row.secondPassYield()), percentText(row.lastPassYield()));
}

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
    case UnitStatus::Error:
        return tr("station error, no reason recorded");
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

YieldRow YieldReport::total(const QVector<YieldRow>& rows)
{
    YieldRow sum;
    for (const YieldRow& r : rows) {
        if (sum.checksum.isEmpty()) {
            sum.checksum = r.checksum;
            sum.recipe = r.recipe;
            sum.revision = r.revision;
        }
        sum.serials += r.serials;
        sum.firstPass += r.firstPass;
        sum.secondPass += r.secondPass;
        sum.lastPass += r.lastPass;
        sum.records += r.records;
        sum.verdicts += r.verdicts;
        sum.passed += r.passed;
        sum.failed += r.failed;
        sum.stationErrors += r.stationErrors;
        sum.running += r.running;
        for (auto it = r.failureReasons.cbegin(); it != r.failureReasons.cend(); ++it)
            sum.failureReasons[it.key()] += it.value();
        for (auto it = r.stationReasons.cbegin(); it != r.stationReasons.cend(); ++it)
            sum.stationReasons[it.key()] += it.value();
    }
    return sum;
}

std::optional<YieldReport::Tables> YieldReport::query(ResultDatabase& db,
                                                      const ResultFilter& filter,
                                                      const ShiftPlan& plan, QString* error)
{
    ResultQueries queries(db);
    const std::optional<QVector<UnitRecord>> units = queries.find(filter, error);
    if (!units)
        return std::nullopt;
    const std::optional<Earlier> earlier = queries.testedBefore(filter, error);
    if (!earlier)
        return std::nullopt;
    Tables tables;
    tables.units = *units;
    tables.perRecipe = perRecipe(*units, *earlier);
    tables.perShift = perShift(*units, plan, *earlier);
    return tables;
}

} // namespace opentop
