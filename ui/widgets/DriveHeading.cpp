#include "ui/widgets/DriveHeading.h"

#include "model/bus/BusDrives.h"

namespace opentop {

DriveHeading::DriveHeading(BusDrives* drives, int slave, const QString& format, QWidget* parent)
    : QLabel(parent)
{
    auto name = [this, drives, slave, format] {
        setText(format.arg(drives->listed(slave).toHtmlEscaped()));
    };
    name();
    connect(drives, &BusDrives::nameChanged, this, [name, slave](int named) {
        if (named == slave)
            name();
    });
}

} // namespace opentop
