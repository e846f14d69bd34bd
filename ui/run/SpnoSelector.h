#pragma once

#include <QComboBox>
#include <optional>

namespace opentop {

class DeviceSession;

// The running data selector of a test run: SPno1–SPnoN, each with the speed and direction the
// drive holds for it ("SPno2 — 1000 r/min, CW"), as a TOP-1 shows them. The data carries the
// running data number N (1-based). It is what the user will select, not what the drive runs:
// until the user picks one it shows the running data the drive reported when last read (its
// "selected" role), and the page's live box shows what the drive runs now.
class SpnoSelector : public QComboBox
{
    Q_OBJECT
public:
    SpnoSelector(DeviceSession* session, QWidget* parent = nullptr);

    // Reads every SPno's speed and direction and the running data the drive runs, and shows
    // them (asynchronous).
    void refreshLabels();
    // The running data the drive reported at the last refresh; nothing when not read.
    std::optional<int> driveSpno() const { return m_driveSpno; }
    // Whether the user has picked an entry since the page opened (the drive's no longer moves it).
    bool userChose() const { return m_userChose; }

signals:
    void labelsRefreshed();

private:
    DeviceSession* m_session;
    std::optional<int> m_driveSpno;
    bool m_userChose = false;
};

} // namespace opentop
