#include "model/run/ExitCheck.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveName.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/session/DeviceSession.h"

namespace opentop {

namespace {
const QString kIoPriority = QStringLiteral("ioPriority");
}

QString DriveLeftBehind::text() const
{
    QStringList what;
    if (running)
        what << state;
    if (busPriority)
        what << ExitCheck::tr("in communication priority (its own inputs cannot start or stop it)");
    return ExitCheck::tr("Machine number %1 (%2): %3")
        .arg(slave)
        .arg(DriveName::nameAndModel(name, model), what.join(QStringLiteral(", ")));
}

QVector<DriveLeftBehind> ExitCheck::collect(const BusDrives& drives,
                                            const DriveStatusPoller& poller)
{
    QVector<DriveLeftBehind> left;
    for (int slave : drives.slaves()) {
        const DriveStatus status = poller.status(slave);
        DriveLeftBehind d;
        d.slave = slave;
        d.model = drives.info(slave).shortModel();
        d.name = drives.name(slave);
        d.running = status.running.value_or(false);
        d.busPriority = status.motionPriority.value_or(false);
        d.inputsControl = status.motionPriority.has_value() && !*status.motionPriority;
        if (!d.running && !d.busPriority)
            continue;
        d.state = status.lastStateText();
        d.lastAnswer = status.lastAnswer;
        if (const DeviceSession* session = drives.session(slave))
            d.canReturn = session->profile().role(kIoPriority) != nullptr;
        left << d;
    }
    return left;
}

} // namespace opentop
