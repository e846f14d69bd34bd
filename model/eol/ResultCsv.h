#pragma once

#include "model/eol/UnitRecord.h"
#include "model/eol/YieldReport.h"

#include <QCoreApplication>

namespace opentop {

// CSV exports of results (RFC 4180: comma separated, CRLF line ends, a field with a comma, a
// quote or a line break in double quotes with its quotes doubled; UTF-8, a header row).
class ResultCsv
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ResultCsv)
public:
    // One row per unit: id, serial, station, operator, started, ended, recipe, revision,
    // checksum, status, failure reason.
    static QByteArray units(const QVector<UnitRecord>& units);
    // One row per measured value of whole records (ResultQueries::load), with the unit's serial.
    static QByteArray measurements(const QVector<UnitRecord>& records);
    // One row per yield row and failure reason.
    static QByteArray yield(const QVector<YieldRow>& rows);
    // Written through OutputFile (atomic for a regular file, through for /dev/stdout).
    static bool save(const QString& path, const QByteArray& csv, QString* error);

    static QString field(const QString& text); // quoted when it must be
    // A record: each field made safe for a spreadsheet (DisplayText::csvCell: control
    // characters escaped, a formula made text), then quoted when it must be.
    static QByteArray line(const QStringList& fields);
};

} // namespace opentop
