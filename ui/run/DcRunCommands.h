#pragma once

#include "model/run/RunControl.h"

#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;

namespace opentop {

class DeviceSession;

// The DC controller's test run commands: a speed set point in the current speed mode's unit
// (checked against its range as it is typed), brake (speed 0) and natural stop (coast, when the
// profile has it). The panel that holds them sends the commands they ask for.
class DcRunCommands : public QWidget
{
    Q_OBJECT
public:
    DcRunCommands(DeviceSession* session, QWidget* parent = nullptr);

    QString speedError() const; // why the speed typed is refused; empty when it is allowed
    // While a command is under way the set point cannot be changed or sent (stops always can).
    void setBusy(bool busy);
    // Shows the unit and range of the current speed mode again (after it was read).
    void updateSpeed();

signals:
    // `starts`: the command may start the motor (a set point other than 0).
    void commandRequested(const RunControl::Command& command, bool starts);

private:
    void requestSpeed();

    DeviceSession* m_session;
    bool m_busy = false;
    QLineEdit* m_speed;
    QLabel* m_speedUnit;
    QLabel* m_speedError;
    QPushButton* m_setSpeed;
};

} // namespace opentop
