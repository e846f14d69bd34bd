#pragma once

#include <QCoreApplication>
#include <QPointer>
#include <QStringList>
#include <QVector>
#include <functional>
#include <optional>

namespace opentop {

class DeviceSession;

// Whether the drives of a communication group follow a run command sent to their parent. A
// child executes every frame sent to the parent without replying, but a DBU takes run commands
// (start, stop, direction, running data, hold/free) only in communication priority: a child in
// I/O priority ignores them, as does one with an active alarm, and it then shows E2h "Cannot
// execute command". Read fresh from the children: before the command (who will follow and why
// not), and after it (who runs, who does not and why).
class GroupFollowers
{
    Q_DECLARE_TR_FUNCTIONS(opentop::GroupFollowers)
public:
    struct Drive
    {
        int slave = 0;
        QString name;                // the machine's name (DriveName), empty: none
        std::optional<bool> follows; // none: its priority could not be read
        QString priority;            // "I/O priority", as the drive's setting names it
        bool alarm = false;          // an alarm is active
        QString why;                 // why it does not follow (or why it is not known)
        // After the command:
        std::optional<bool> running; // none: not read
        QString speed;               // "1200 r/min"
        QString commError;           // its communication error code, explained (not 0)
    };
    using Done = std::function<void(const QVector<Drive>&)>;

    // Reads each child's control priority and alarm state.
    static void readBefore(const QVector<DeviceSession*>& children, Done done);
    // Reads each child's run state, speed, priority, alarm and communication error code.
    static void readAfter(const QVector<DeviceSession*>& children, Done done);

    // "Machine number 2 follows it (communication priority). Machine number 150 does not
    // follow it: …" One line per drive, for the question before the command.
    static QStringList beforeLines(const QVector<Drive>& drives);
    // "Machine number 2 runs (1200 r/min). Machine number 150 did not start: …"
    static QStringList afterLines(const QVector<Drive>& drives);
    // The drives that will not follow (or whose priority could not be read).
    static QVector<int> notFollowing(const QVector<Drive>& drives);

private:
    static void read(const QVector<DeviceSession*>& children, bool after, Done done);
    static Drive decode(DeviceSession& session, bool after);
    static QString listed(const Drive& d); // "2 (Infeed conveyor 3)"
};

} // namespace opentop
