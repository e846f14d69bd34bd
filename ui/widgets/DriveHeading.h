#pragma once

#include <QLabel>

namespace opentop {

class BusDrives;

// A page's heading that names its drive with the machine's name, and follows a rename while
// the page is open: "Test run of machine number 1 (Infeed conveyor 3)".
class DriveHeading : public QLabel
{
    Q_OBJECT
public:
    // `format`: rich text with %1 for the drive, "<b>Test run of machine number %1</b>".
    DriveHeading(BusDrives* drives, int slave, const QString& format, QWidget* parent = nullptr);
};

} // namespace opentop
