#pragma once

#include "transport/ConnectionSettings.h"
#include "transport/LineFormat.h"

#include <QDialog>

class QAction;
class QComboBox;
class QMenu;
class QLabel;
class QSpinBox;

#include <functional>

namespace opentop {

class BusDrives;

// Asks for the line format a drive talks at where it is not the port's (a DC controller at
// 8E1 on a DBU bus at 8N1), with how a drive of that family is changed to join the bus. Used
// to add a drive by hand (machine number and format) and from the bus list's context menu
// (the format of a listed drive). An unset line() means the port's own.
class DriveLineDialog : public QDialog
{
    Q_OBJECT
public:
    // `slave` 0: the machine number is asked too. `family`: the drive's, empty when unknown
    // (the help of every family that has one is shown then).
    DriveLineDialog(const ConnectionSettings& port, int slave, const LineFormat& current,
                    const QString& family, QWidget* parent = nullptr);

    int slave() const;
    // The chosen format; unset for the port's.
    LineFormat line() const;
    QComboBox* formatBox() const { return m_format; }
    QSpinBox* slaveBox() const { return m_slave; }
    // Why the typed format cannot be used; empty when it can.
    QString problem() const;

    void accept() override;

    // Add drive: asks the machine number and format (window-modal, not blocking); on OK sets
    // the format (BusDrives::setLine) and calls `add` with the number.
    static DriveLineDialog* askToAdd(QWidget* parent, BusDrives* drives, int suggested,
                                     std::function<void(int)> add);
    // The context menu's "Line format…" for one listed drive; on OK sets its format and calls
    // `identify` (a drive absent at the port's format may answer at its own).
    static QAction* addMenuAction(QMenu* menu, BusDrives* drives, int slave,
                                  std::function<void(int)> identify);

private:
    ConnectionSettings m_port;
    QSpinBox* m_slave = nullptr;
    QComboBox* m_format = nullptr;
    QLabel* m_error = nullptr;
};

} // namespace opentop
