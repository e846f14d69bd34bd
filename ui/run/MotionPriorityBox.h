#pragma once

#include <QFrame>

class QLabel;

namespace opentop {

class BusDrives;
class DeviceSession;

// Shown while a drive does not take motion commands over the bus (its "motionPriority" role
// does not hold): explains what its current setting means and what switching does, and offers
// to switch after a confirmation; and the way back to I/O priority (the "ioPriority" role).
class MotionPriorityBox : public QFrame
{
    Q_OBJECT
public:
    MotionPriorityBox(BusDrives* drives, DeviceSession* session, QWidget* parent = nullptr);

    // `current`: the setting's text as read, e.g. "I/O priority".
    void setCurrent(const QString& current);
    QString explanation() const;
    // Asks (over `parent`), then gives the drive back to its input terminals.
    void askToReturn(QWidget* parent);

signals:
    void switching(const QString& text);
    // The write finished; `message` says what became of it.
    void switched(bool ok, const QString& message);

private:
    // The drives a priority write to this one also reaches (group children), as a paragraph.
    QString alsoReaches() const;
    void askToSwitch();
    void sendSwitch();
    QString wantedLabel() const;

    BusDrives* m_drives;
    DeviceSession* m_session;
    QLabel* m_text;
};

} // namespace opentop
