#pragma once

#include "model/run/RunControl.h"

#include <QList>
#include <QWidget>

class QPushButton;

namespace opentop {

class DeviceSession;
class SpnoSelector;

// A DBU's test run commands, the roles its profile has: start, stop, CW, CCW, hold, free, the
// running data selection (SpnoSelector) and the way back to I/O priority, as a TOP-1 offers.
// The panel that holds them sends the commands they ask for.
class DbuRunCommands : public QWidget
{
    Q_OBJECT
public:
    DbuRunCommands(DeviceSession* session, QWidget* parent = nullptr);

    SpnoSelector* spnoSelector() const { return m_spno; } // nullptr: no running data selection
    // While a command is under way nothing but a stop can be asked for.
    void setBusy(bool busy);
    // Only a drive in communication priority is offered the way back to I/O priority.
    void setIoReturnVisible(bool visible);

signals:
    // `starts`: the command may start the motor.
    void commandRequested(const RunControl::Command& command, bool starts);
    void ioPriorityRequested();

private:
    QPushButton* addButton(const QString& text, const QString& name);

    SpnoSelector* m_spno = nullptr;
    QPushButton* m_ioButton = nullptr;
    QList<QWidget*> m_whileIdle; // disabled while a command is under way (stops never are)
};

} // namespace opentop
