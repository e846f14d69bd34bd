#pragma once

#include "model/run/ExitPlan.h"

#include <QObject>
#include <QStringList>
#include <QVector>
#include <functional>

namespace opentop {

class BusDrives;

// Carries out what the user chose for those drives: stop them (each family's stop broadcast,
// then every listed drive confirmed stopped), give control back to their inputs (the
// "ioPriority" role written and read back), or both in that order (ExitPlan). Asynchronous;
// `done` gets one line per failure, naming the drive.
class ExitActions : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const QStringList& failures)>;
    explicit ExitActions(BusDrives* drives, QObject* parent = nullptr);

    // What `choice` of `plan` says: for StopAndGiveBack, a drive not confirmed stopped stays in
    // communication priority (its inputs are not handed a motor the program could not stop).
    void leave(const ExitPlan& plan, ExitPlan::Choice choice, Done done);
    void returnToIoPriority(const QVector<int>& slaves, Done done);

private:
    // Stops `slaves`; `stopped`: the ones confirmed stopped.
    void stop(const QVector<int>& slaves,
              std::function<void(const QStringList& failures, const QVector<int>& stopped)> done);
    void returnNext(QVector<int> slaves, QStringList failures, Done done);

    BusDrives* m_drives;
};

} // namespace opentop
