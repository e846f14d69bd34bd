#pragma once

#include <QCoreApplication>
#include <QString>

namespace opentop {

class DeviceSession;

// The name a user gives a machine ("Infeed conveyor 3") and how every message names a drive:
// the one place, so that questions, pages, files, reports and the command line name a drive
// the same way ("machine number 1 (Infeed conveyor 3)"). Names are kept per bus (BusMemory)
// and carried by the drive's session (DeviceSession::machineName).
class DriveName
{
    Q_DECLARE_TR_FUNCTIONS(opentop::DriveName)
public:
    static constexpr int kMaxLength = 40;

    // `name` as it is kept: spaces at either end removed.
    static QString cleaned(const QString& name);
    // Why `name` cannot name a machine (too long, a control character, a line break); empty
    // when it can. An empty name is allowed: it removes the name.
    static QString problem(const QString& name);

    // Inside a sentence: "machine number 1 (Infeed conveyor 3)", "machine number 1".
    static QString text(int slave, const QString& name);
    // At the start of a sentence or as a title: "Machine number 1 (Infeed conveyor 3)".
    static QString title(int slave, const QString& name);
    // In a list of drives: "1 (Infeed conveyor 3)", "1".
    static QString listed(int slave, const QString& name);
    // What goes in brackets beside a number with the model: "Infeed conveyor 3, DBU200-D",
    // "DBU200-D".
    static QString nameAndModel(const QString& name, const QString& model);
    // With the model, for files and their comparison: "drive 1 (Infeed conveyor 3, DBU200-D)",
    // "drive 1 (DBU200-D)".
    static QString withModel(int slave, const QString& name, const QString& model);
    // The same for a drive's session (its machine number and name).
    static QString text(const DeviceSession* session);
    static QString title(const DeviceSession* session);
    static QString listed(const DeviceSession* session);
};

} // namespace opentop
