#pragma once

#include "model/eol/UnitRecord.h"
#include "model/files/BackupDevice.h"

#include <QObject>
#include <QVector>
#include <functional>

namespace opentop {

class DeviceSession;
class Restorer;
struct RestorePlan;

// One position's recipe settings at the end-of-line run (EolDriveRun's write and verify
// phases): only those that differ are written (Restorer: in dependency order, each read back,
// the DC controller's stored), then every one is read back once more. Keeps each value as the
// unit's record holds it (WrittenValue: the profile's English, written, read back, verified).
class EolSettingsWriter : public QObject
{
    Q_OBJECT
public:
    // `done` with why not, in words (empty: done); never inside the call.
    using Done = std::function<void(const QString& failure)>;

    EolSettingsWriter(DeviceSession* session, const BackupDevice& target, int machineNumber,
                      QObject* parent = nullptr);

    // Writes the settings that differ; the failure names the first setting that failed.
    void write(Done done);
    // Reads every setting back; the failure names the first that does not hold.
    void verify(Done done);
    // Writing (a write and its read-back belong together: cancel() stops after it).
    bool isWriting() const { return m_restorer != nullptr; }
    void cancel();
    // The drive's run ended: answers from now on are dropped, `done` is not called.
    void drop() { m_dropped = true; }
    const QVector<WrittenValue>& values() const { return m_written; }

private:
    QString written(const RestorePlan& plan); // the values recorded; why not done

    DeviceSession* m_session;
    BackupDevice m_target;
    int m_machineNumber;
    Restorer* m_restorer = nullptr;
    bool m_dropped = false;
    QVector<WrittenValue> m_written;
};

} // namespace opentop
