#pragma once

#include <QString>
#include <QVector>

namespace opentop {

// A code a device reports (alarm, warning, communication error) with what an engineer needs.
struct CodeEntry
{
    qint64 code = 0;
    QString panel; // what the drive's display shows, e.g. "AL00B", "WR017"
    QString name;
    QString reset;     // how it is cleared: "alarm-reset", "power", "auto", "none"
    QString resetText; // the same, for people
    QString cause;
    QString remedy;
    QString led;           // DBU MONITOR LED colour while active: red, purple, blue
    int exceptionCode = 0; // communication errors: the Modbus exception code that goes with it
    bool retry = false;    // communication errors: nothing was executed, send it again (busy)

    // How a code is cleared, for people: "Alarm-Reset", "power cycle", "by itself".
    static QString clearedByText(const QString& reset);
    // The code with what it means and what to do, as one text for a message: "E2h Cannot
    // execute command: <cause> What to do: <remedy>" (the profile's words, translated).
    QString explained() const;
};

struct CodeTable
{
    QString id;
    QString label;
    QVector<CodeEntry> entries;

    const CodeEntry* find(qint64 code) const;
};

} // namespace opentop
