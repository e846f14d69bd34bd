#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QVector>
#include <functional>

namespace opentop {

class BusDrives;
class DriveStatusPoller;

// A drive the program would leave behind if it let go of the bus now.
struct DriveLeftBehind
{
    int slave = 0;
    QString model;            // "DBU200-D"
    bool running = false;     // by the last status poll
    bool busPriority = false; // holds the setting motion over the bus needs ("motionPriority")
    bool canReturn = false;   // the profile names the value that gives control back ("ioPriority")
    bool inputsControl = false; // read to be in I/O priority: it runs from its own inputs
    QString state;              // "Running CW", as the bus list says it
    QDateTime lastAnswer;       // when what is said here was read (invalid: never)

    // "Machine number 1 (DBU200-D): Running CW, in Communication priority"
    QString text() const;
};

// What quitting or disconnecting would leave behind: drives running, and drives left in the
// priority that makes them take motion commands from the bus only (a DBU in communication
// priority cannot be started or stopped by the machine's own inputs). Taken from the status
// poller's last cycle, which every view keeps running while connected.
class ExitCheck
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ExitCheck)
public:
    static QVector<DriveLeftBehind> collect(const BusDrives& drives,
                                            const DriveStatusPoller& poller);
};

} // namespace opentop
