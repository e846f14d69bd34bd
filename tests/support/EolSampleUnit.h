#pragma once

// A unit record with everything a record can hold, and text that tests quoting and escaping
// (commas, quotes, line breaks, <&>, non-ASCII), for the results database and certificate tests.
#include "model/eol/UnitRecord.h"
#include "model/eol/UnitRecordJson.h"

#include <QTimeZone>

namespace opentop {

inline void PrintTo(UnitStatus status, std::ostream* os)
{
    *os << unitStatusName(status).toStdString();
}

// GoogleTest shows a record that differs as its JSON.
inline void PrintTo(const UnitRecord& record, std::ostream* os)
{
    *os << UnitRecordJson::toBytes(record).toStdString();
}

} // namespace opentop

namespace opentop::test {

inline UnitRecord eolSampleUnit(const QString& serial, UnitStatus status = UnitStatus::Fail)
{
    UnitRecord r;
    r.serial = serial;
    r.station = QStringLiteral("line-1/station-A");
    r.operatorName = QStringLiteral("Jürgen \"JJ\" O'Neil");
    r.started = QDateTime(QDate(2026, 11, 24), QTime(13, 5, 7, 123), QTimeZone::utc());
    r.ended = r.started.addMSecs(48250);
    r.recipeName = QStringLiteral("pump-200, 2 drives");
    r.recipeRevision = QStringLiteral("7b");
    r.recipeChecksum = QStringLiteral("sha256:9f86d081884c7d659a2feaa0c55ad015");
    r.status = status;
    r.drives = {{1, QStringLiteral("DBU"), QStringLiteral("DBU200"), QStringLiteral("1.07"),
                 VariantSource::Probed,
                 QStringLiteral("Speed lower limit = 280 r/min accepted, 0 written back")},
                {2, QStringLiteral("DBU"), QStringLiteral("DBU400"), QStringLiteral("1.10"),
                 VariantSource::Assumed, QStringLiteral("the recipe's only variant")}};
    r.writtenValues = {{1, QStringLiteral("spno2.speed"), QStringLiteral("Speed 2"),
                        QStringLiteral("1500 r/min"), true, true, QStringLiteral("1500 r/min")},
                       {1, QStringLiteral("accel"), QStringLiteral("Acceleration time"),
                        QStringLiteral("0.5 s"), false, true, QStringLiteral("0.5 s")},
                       {2, QStringLiteral("brake.mode"), QStringLiteral("Brake <mode> & \"stop\""),
                        QStringLiteral("ramp,\nthen hold"), true, false,
                        QStringLiteral("free run")}};
    r.measurements = {{1, QStringLiteral("hold CW 1500 r/min"), QStringLiteral("speed mean"),
                       1498.25, QStringLiteral("r/min"), 1450.0, 1550.0, true},
                      {1, QStringLiteral("hold CW 1500 r/min"), QStringLiteral("load max"), 87.5,
                       QStringLiteral("%"), std::nullopt, 120.0, true},
                      {2, QStringLiteral("stop"), QStringLiteral("stop time"), 0.1 + 0.2,
                       QStringLiteral("s"), 0.0, std::nullopt, true},
                      {2, QStringLiteral("hold CCW"), QStringLiteral("speed min"), 1203.000000001,
                       QStringLiteral("r/min"), 1450.0, 1550.0, status == UnitStatus::Pass}};
    if (status != UnitStatus::Pass) {
        r.failureReason = QStringLiteral("drive 2: speed min 1203 r/min below 1450 r/min");
        r.traffic = {QStringLiteral("13:05:50.101 → 2: read Speed (0x0100) ×2"),
                     QStringLiteral("13:05:50.125 ← 2: 1203 r/min, \"ok\""),
                     QStringLiteral("13:05:50.301 ✕ 2: no reply (timeout 200 ms)")};
    }
    return r;
}

} // namespace opentop::test
