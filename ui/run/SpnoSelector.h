#pragma once

#include <QComboBox>

namespace opentop {

class DeviceSession;

// The running data selector of a test run: SPno1–SPnoN, each with the speed and direction the
// drive holds for it ("SPno2 — 1000 r/min, CW"), as a TOP-1 shows them. The data carries the
// running data number N (1-based).
class SpnoSelector : public QComboBox
{
    Q_OBJECT
public:
    SpnoSelector(DeviceSession* session, QWidget* parent = nullptr);

    // Reads every SPno's speed and direction and shows them (asynchronous).
    void refreshLabels();

signals:
    void labelsRefreshed();

private:
    DeviceSession* m_session;
};

} // namespace opentop
