#include "EditorRegistry.h"

#include "DcControllerPage.h"
#include "DriveWorkspace.h"
#include "IoTerminalsPage.h"
#include "RunningDataPage.h"
#include "SpeedUnitsPage.h"

namespace opentop {

void registerBuiltInEditors()
{
    DriveWorkspace::registerEditor(
        QStringLiteral("runningData"),
        [](DeviceParameters* p, QWidget* parent) { return new RunningDataPage(p, parent); });
    DriveWorkspace::registerEditor(
        QStringLiteral("ioTerminals"),
        [](DeviceParameters* p, QWidget* parent) { return new IoTerminalsPage(p, parent); });
    DriveWorkspace::registerEditor(
        QStringLiteral("speedUnits"),
        [](DeviceParameters* p, QWidget* parent) { return new SpeedUnitsPage(p, parent); });
    DriveWorkspace::registerEditor(
        QStringLiteral("dcController"),
        [](DeviceParameters* p, QWidget* parent) { return new DcControllerPage(p, parent); });
}

} // namespace opentop
