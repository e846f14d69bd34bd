#pragma once

#include "model/run/GroupFollowers.h"

#include <QObject>
#include <QStringList>
#include <QVector>
#include <functional>
#include <optional>

namespace opentop {

class BusDrives;

// What a start of a drive will do, read from the drives before it is asked for: which running
// data (SPno) is selected, its speed and direction as the drive holds them, a deceleration the
// manual advises against (RunningData), and the other drives the start also reaches through
// their communication group (BusGroups, the groups read now, not assumed), each with whether it
// follows the start (GroupFollowers: its control priority and alarm, read now).
class StartPreview : public QObject
{
    Q_OBJECT
public:
    struct Result
    {
        int slave = 0;
        int spno = 0;      // 0: not known
        QString speed;     // "1000 r/min"
        QString direction; // "CW"
        bool directionFromCommand = false;
        QString warning; // the deceleration advice, or empty
        QString drive;   // "1 (Infeed conveyor 3)": the number and the machine's name
        QVector<int> alsoReaches;
        QStringList alsoReachesNames;             // the same, named as `drive`
        QString reach;                            // BusGroups::reachText
        QVector<GroupFollowers::Drive> followers; // the drives reached: do they follow?
        QStringList unread;                       // labels of what could not be read
        // The lines of the start confirmation.
        QString text() const;
        // The whole start question; `speedCommand`: a speed set point that starts the motor
        // (a DC controller), empty for a start command.
        QString question(const QString& speedCommand = QString()) const;
        QString named() const; // `drive`, or the number alone
    };
    using Done = std::function<void(const Result&)>;

    explicit StartPreview(BusDrives* drives, QObject* parent = nullptr);

    // `commandedCcw`: the direction command sent since the running data was selected (it
    // overrides the SPno's own direction on a DBU); none when there was none.
    void read(int slave, std::optional<bool> commandedCcw, Done done);

private:
    struct Job;
    void readSelection(const std::shared_ptr<Job>& job);
    void readSpno(const std::shared_ptr<Job>& job);
    void readGroups(const std::shared_ptr<Job>& job);
    void readFollowers(const std::shared_ptr<Job>& job);

    BusDrives* m_drives;
};

} // namespace opentop
