#pragma once

#include "model/run/RunControl.h"

#include <QSet>
#include <QWidget>
#include <optional>

class QLabel;
class QVBoxLayout;

namespace opentop {

class BusDrives;
class CommandReadBack;
class DbuRunCommands;
class DcRunCommands;
class DeviceSession;
class MonitorHub;
class MotionPriorityBox;
class RunLiveState;
class SpnoSelector;
class StartPreview;

// Test run of one drive by its roles (RunControl): start, stop, direction, running data
// selection, hold and free for a DBU; a speed set point in the current speed mode's unit,
// brake (speed 0) and natural stop (coast) for the DC controller. The commands are enabled only
// while the drive takes motion commands over the bus ("motionPriority"); otherwise the panel
// explains how to switch and offers to do it after a confirmation, and once switched offers the
// way back to I/O priority. Starting a motor asks once per drive and program run, and every
// time the start also reaches other drives (communication group); the question says which
// running data, speed and direction will run and which drives of its communication group follow
// (StartPreview); after a motion command each of them is read and reported. With a MonitorHub the
// page shows what the drive does now (RunLiveState, watched while visible); after each command the
// state read back is shown with its time.
class TestRunPanel : public QWidget
{
    Q_OBJECT
public:
    TestRunPanel(BusDrives* drives, int slave, QWidget* parent = nullptr);

    int slave() const { return m_slave; }
    // Whether the drive takes motion commands over the bus (read by refresh()).
    bool commandsEnabled() const { return m_enabled; }
    QString priorityExplanation() const;
    QString stateText() const;
    QString messageText() const;
    QString speedError() const;     // why the speed typed is refused; empty when it is allowed
    QString pollingWarning() const; // the communication-loss warning shown, or empty
    // Polling paused: a DC controller with a communication loss stop time brakes the motor.
    void setPollingActive(bool active);
    // Shows the drive's live state from `hub` (and watches the drive while visible).
    void setMonitorHub(MonitorHub* hub);
    RunLiveState* liveState() const { return m_live; }
    SpnoSelector* spnoSelector() const { return m_spno; }
    // The text of the last start question (for the log and tests).
    QString lastStartQuestion() const { return m_lastQuestion; }

    // Drives whose start the user has confirmed in this program run.
    static bool startConfirmed(int slave) { return s_confirmed.contains(slave); }
    static void forgetConfirmations() { s_confirmed.clear(); }

public slots:
    // Reads the control priority (DBU) or speed mode and communication loss time (DC).
    void refresh();

signals:
    void refreshed();
    // A command finished (sent or refused) and the state read back is shown.
    void commandFinished(bool ok);

private:
    void buildDbu();
    void buildDc();
    void run(const RunControl::Command& command, bool starts);
    void send(const RunControl::Command& command);
    void showOutcome(const RunControl::Outcome& outcome);
    void finishCommand(bool ok);
    void updateEnabled();
    void updateWarning();
    void setMessage(const QString& text, bool error);
    void askToStart(const RunControl::Command& command);

    BusDrives* m_drives;
    int m_slave;
    DeviceSession* m_session;
    RunControl m_control;
    bool m_isDc = false;
    bool m_enabled = false;
    bool m_busy = false;
    bool m_pollingActive = true;
    double m_commLossSeconds = 0;
    QString m_currentPriority; // the priority setting's text, e.g. "I/O priority"

    MotionPriorityBox* m_priorityBox = nullptr;
    QWidget* m_commands = nullptr;
    QVBoxLayout* m_side = nullptr; // the right-hand column
    SpnoSelector* m_spno = nullptr;
    RunLiveState* m_live = nullptr;
    StartPreview* m_preview = nullptr;
    std::optional<bool> m_commandedCcw; // a CW/CCW command sent since the last selection
    QString m_lastQuestion;
    DbuRunCommands* m_dbu = nullptr; // a DBU's commands
    DcRunCommands* m_dc = nullptr;   // the DC controller's commands
    QLabel* m_warning = nullptr;
    QLabel* m_message = nullptr;
    CommandReadBack* m_state = nullptr;

    static QSet<int> s_confirmed;
};

} // namespace opentop
