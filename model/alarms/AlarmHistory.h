#pragma once

#include "model/alarms/AlarmRecords.h"
#include "model/profile/CodeTable.h"
#include "model/session/DeviceSession.h"

#include <QObject>
#include <QStringList>
#include <QVector>
#include <functional>
#include <memory>
#include <optional>

namespace opentop {

struct ParameterMeta;

// A drive's alarm and warning records and its communication error register read from the drive
// (decoded by AlarmRecords); alarm reset and erasing the records. Tables and roles come from the
// profile: code tables "alarm", "warning" and "comm_error"; roles "alarmActive", "alarmReset",
// "eraseAlarms", "eraseWarnings".
class AlarmHistory : public QObject
{
    Q_OBJECT
public:
    using Record = AlarmRecords::Record;
    using History = AlarmRecords::History;
    using Report = AlarmRecords::Report;
    using ReportDone = std::function<void(const Report&)>;

    struct ResetOutcome
    {
        bool sent = false; // the reset command reached the drive
        bool ok = false;   // the drive accepted it
        bool wasActive = false;
        std::optional<CodeEntry> alarm;  // the alarm active before the reset
        std::optional<bool> stillActive; // read after the reset
        bool powerCycleNeeded = false;
        QString error;       // the write's error, if any
        QString explanation; // what happened and what to do, for people
    };
    using ResetDone = std::function<void(const ResetOutcome&)>;

    struct ClearOutcome
    {
        bool ok = false;
        QStringList cleared; // labels of the tables erased ("Alarm codes")
        QStringList errors;
        int erasedRecords = 0; // non-empty records before erasing
        bool verified = false; // read back empty
    };
    using ClearDone = std::function<void(const ClearOutcome&)>;

    explicit AlarmHistory(DeviceSession* session, QObject* parent = nullptr);

    // Whether the profile has any record table or a communication error register.
    bool supported() const;
    bool canReset() const;
    bool canClear() const;
    // What reset() and clearRecords() write, for a "would send" message.
    QStringList resetPlan() const;
    QStringList clearPlan() const;

    // Reads every record and the error register in as few requests as the drive allows.
    void read(ReportDone done);
    // Sends the "alarmReset" role, then reads whether the alarm is still active and explains
    // when only a power cycle clears it.
    void reset(ResetDone done);
    // Erases the alarm and warning records ("eraseAlarms", "eraseWarnings"), then reads them
    // back to confirm they are empty.
    void clearRecords(ClearDone done);

    // Setting whose value (role "alarmEraseByPower") means alarms clear by a power restart only.
    QString eraseMethodParameter() const;

private:
    struct ResetState
    {
        ResetOutcome outcome;
        bool powerMethod = false; // the drive clears alarms by a power restart only
        QString methodText;       // "core.alarm_erase = Restart power"
    };
    void sendReset(const DeviceSession::ReadManyOutcome& before, ResetDone done);
    void finishReset(const std::shared_ptr<ResetState>& state, std::optional<bool> still,
                     ResetDone done);
    void writeRoles(const QStringList& roles, std::function<void(QStringList errors)> done);

    DeviceSession* m_session;
    AlarmRecords m_records;
};

} // namespace opentop
