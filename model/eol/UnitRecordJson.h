#pragma once

#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <QJsonObject>

namespace opentop {

// A unit record as JSON: the machine-readable certificate (docs/eol-results.md), and the form
// tests compare records in. Times are UTC ISO 8601 with milliseconds; a limit that is not set is
// absent, not null.
class UnitRecordJson
{
    Q_DECLARE_TR_FUNCTIONS(opentop::UnitRecordJson)
public:
    static constexpr int kFormatVersion = 1;
    static QString formatName() { return QStringLiteral("opentop-unit-record"); }

    static QJsonObject toJson(const UnitRecord& record);
    static QByteArray toBytes(const UnitRecord& record); // indented, keys sorted
    // Refuses another format or a newer version, a missing serial, an unknown status.
    static std::optional<UnitRecord> fromJson(const QJsonObject& json, QString* error);
    static std::optional<UnitRecord> fromBytes(const QByteArray& data, QString* error);

    // The one text form of a record's times, in JSON and in the database alike.
    static QString timeText(const QDateTime& time);
    static QDateTime timeFromText(const QString& text);
};

} // namespace opentop
