#pragma once

#include "model/profile/CodeTable.h"

#include <QCoreApplication>
#include <QHash>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

class DeviceSession;
struct ParameterMeta;

// A drive's alarm and warning records and its communication error register as the profile lays
// them out (code tables "alarm", "warning", "comm_error"), and their raw values decoded into
// what an engineer reads. Reading them from the drive and the reset and erase procedures are
// AlarmHistory's.
class AlarmRecords
{
    Q_DECLARE_TR_FUNCTIONS(opentop::AlarmRecords)
public:
    // One record slot, 1 = newest.
    struct Record
    {
        int index = 0;
        qint64 code = 0;
        bool empty = true;              // code 0: nothing recorded in this slot
        std::optional<CodeEntry> entry; // the code table's entry; none for unknown codes
    };
    struct History
    {
        QString table; // "alarm", "warning"
        QString label; // the code table's label
        QVector<Record> records;
        bool ok = false;
        QString error;
        int used() const;
        // Codes present, each once, newest first.
        QVector<CodeEntry> distinctEntries() const;
    };
    struct Report
    {
        bool ok = false;            // everything could be read
        QVector<History> histories; // alarm, then warning (those the profile has)
        QString commErrorParameter; // e.g. "status.comm_error"; empty when the profile has none
        std::optional<qint64> commErrorCode;
        std::optional<CodeEntry> commError; // decoded; none for 0 or unknown codes
        std::optional<bool> alarmActive;
        // The drive is set to clear every alarm by a power restart (see eraseMethodParameter).
        bool powerRestartOnly = false;
        QString eraseMethod; // "core.alarm_erase = Restart power"; empty when not known
        int requests = 0;
        QStringList errors;
    };

    explicit AlarmRecords(const DeviceSession* session);

    QVector<const ParameterMeta*> recordParameters() const;
    const ParameterMeta* commErrorMeta() const;
    // Setting whose value (role "alarmEraseByPower") means alarms clear by a power restart only.
    QString eraseMethodParameter() const;
    bool eraseMethodIsPower(double raw) const;
    // Every parameter a report needs, in one list for DeviceSession::readMany.
    QStringList parametersToRead() const;
    // `raw` holds the values read, `errors` why the others could not be read.
    Report decode(const QHash<QString, double>& raw, const QHash<QString, QString>& errors) const;

private:
    const DeviceSession* m_session;
};

} // namespace opentop
