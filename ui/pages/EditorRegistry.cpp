#include "ui/pages/EditorRegistry.h"

#include "ui/pages/DcControllerPage.h"
#include "ui/pages/IoTerminalsPage.h"
#include "ui/pages/RunningDataPage.h"
#include "ui/pages/SpeedUnitsPage.h"
#include "ui/workspace/DriveWorkspace.h"

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
