#pragma once

#include "model/files/BackupDevice.h"
#include "model/profile/ValueContext.h"

#include <QCoreApplication>
#include <QHash>
#include <QStringList>
#include <QVector>

namespace opentop {

// What a restore does to one drive, parameter by parameter, and afterwards what it did. Built
// in two steps: check() before anything is sent (family, variant, every value allowed, write
// order), build() once the drive's values are known (what differs).
//
// Write order: parameters others depend on first (the control mode before the input
// functions), then the rest in profile order, communication settings last (a serial lock that
// is released goes before the settings it locks, one that is set after them), then one store
// command per store group that something written needs, so that settings of the DC controller
// survive power-off (none when nothing it stores was written).
class RestorePlan
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RestorePlan)
public:
    struct Item
    {
        enum class Action
        {
            Keep,  // the drive already holds the file's value
            Write, // differs: write and read back
            Store, // a store command after the writes
        };
        enum class Status
        {
            Pending,
            Unchanged,
            Verified, // written and read back (store commands: written)
            Failed,
            NotAttempted, // after an interruption or a communication failure
            NotConfirmed, // sent, but no reply: the drive may or may not hold it
        };
        QString parameter;
        Action action = Action::Keep;
        Status status = Status::Pending;
        QVector<quint16> fileRegisters;
        QVector<quint16> deviceRegisters; // as the drive held them before the restore
        QString fileText;                 // "2.5 s"
        QString deviceText;
        QString writeText;     // the exact raw form handed to DeviceSession::write
        QString error;         // why it failed
        bool mismatch = false; // the drive holds another value after the write
    };

    enum class Outcome
    {
        Planned,       // dry run, or not run yet
        Done,          // everything differing written and verified
        Refused,       // nothing sent: family, variant or a value not allowed
        Communication, // a transaction failed; the items say what was written
        Mismatch,      // a value read back differently
        Interrupted,   // cancelled; the items say what was written
    };

    int slave = 0;
    QString title;       // the file's drive: "drive 1 (DBU200-D)"
    QString machineName; // the name of the machine restored to (DriveName), empty: none
    Outcome outcome = Outcome::Planned;
    bool attempted = true;   // false: the bus failed or the user stopped before this drive
    QString reason;          // for a refusal or failure, for people
    bool deviceRead = false; // build() ran: the drive's values are known and compared
    QStringList problems;    // every value that may not be written (a refusal)
    QStringList notes;
    QVector<Item> items; // in write order

    // When the plan writes the family's serial lock on: SerialLock::warning (what it does and how
    // to undo it, naming parameters as `naming` does), for the question before writing; build()
    // also adds it to the notes. Empty when it does not.
    QString lockWarning(const Profile& profile, const ValueContext& naming = {}) const;

    static RestorePlan check(const Profile& liveProfile, const QString& liveVariant,
                             const BackupDevice& file);
    // `live`: the drive's registers of every parameter of the file; `unstored`: store commands
    // the drive needs for writes made earlier (StoreTracker). Keeps the store commands that a
    // write of the plan or `unstored` needs, drops the others and says which and why.
    void build(const Profile& profile, const QString& liveVariant,
               const QHash<QString, QVector<quint16>>& live, const QStringList& unstored = {});

    int count(Item::Status status) const;
    int count(Item::Action action) const;
    bool refused() const { return outcome == Outcome::Refused; }
    static bool isCommunicationSetting(const Profile& profile, const ParameterMeta& meta);

    static QString actionText(Item::Action action);
    static QString statusText(const Item& item);
    static QString outcomeText(Outcome outcome);
    static QString outcomeKey(Outcome outcome); // stable ids for JSON: "done", "refused", ...
    static QString statusKey(Item::Status status);

private:
    void keepNeededStores(const Profile& profile, const QStringList& unstored);
};

} // namespace opentop
