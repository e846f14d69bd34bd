#pragma once

#include "model/monitor/DeviceMonitor.h"

#include <QTimer>
#include <QWidget>
#include <optional>

class QLabel;
class QSplitter;

namespace opentop {

class DeviceParameters;
class MonitorDetails;
class MonitorHub;
class MonitorPollBar;
class MotorSpeedBox;
class PanelMirrorView;
class TerminalLamps;
class StaleLook;
class TrendChart;

// A drive, live: current and target speed in r/min and in the drive's display unit, load,
// running state and direction, selected running data, control mode and priority, the
// terminals as lamps and the active alarm — every value of the profile's "monitor" role, laid
// out from the profile. Beside them the drive's own panel and LED mirrored (when the profile
// has a "panelDisplay" role), for a DC controller the motor speed worked out from the
// commutation frequency; below, a trend of the speeds and the load. Polls through the
// MonitorHub while the page is shown, and records the drive's trend once a second while the
// page exists but is out of sight.
class MonitorPage : public QWidget
{
    Q_OBJECT
public:
    MonitorPage(MonitorHub* hub, DeviceParameters* parameters, QWidget* parent = nullptr);

    int slave() const { return m_slave; }
    // What the page shows for a parameter of the sample ("1500 r/min"); empty before a sample.
    QString valueText(const QString& parameter) const;
    QString currentSpeedText() const;
    QString displaySpeedText() const; // in the drive's display unit, when it has one
    QString alarmText() const;
    QString statusText() const;
    PanelMirrorView* panel() const { return m_panel; }
    TerminalLamps* lamps(const QString& parameter) const;
    TrendChart* chart() const { return m_chart; }
    int samplesShown() const { return m_samples; }
    // The line above the values: their age and the sample rate, or why they are not live.
    QString pollText() const;
    // Whether the values shown are live (monitor/Freshness), as the page shows them.
    StaleLook* staleLook() const { return m_look; }
    // DC controller: commutations per motor revolution for the r/min read-out (0: not set).
    void setCommutationsPerRevolution(double count);

protected:
    void showEvent(QShowEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;
    // Divides the height between the values and the chart, once.
    void divide();
    void hideEvent(QHideEvent* event) override;

private:
    void showSample(const MonitorSample& sample);
    void showPanel(const MonitorSample& sample);
    void showError(const QString& text);
    // The age of the values, greyed when they are not live.
    void showFreshness();
    QWidget* buildReadouts();
    QWidget* buildSide();

    MonitorHub* m_hub;
    DeviceParameters* m_parameters;
    int m_slave;
    MonitorPollBar* m_bar; // poll rate, pause, the values' age
    QLabel* m_current;
    QLabel* m_currentDisplay;
    QLabel* m_target;
    QLabel* m_load;
    QLabel* m_state;
    QLabel* m_alarm;
    MonitorDetails* m_details = nullptr;
    PanelMirrorView* m_panel = nullptr;
    MotorSpeedBox* m_motorSpeed = nullptr; // DC controller only
    TrendChart* m_chart;
    StaleLook* m_look = nullptr;
    QString m_lastError;
    QSplitter* m_splitter = nullptr; // the values above, the chart below
    bool m_userDivided = false;      // the user dragged the splitter: kept from then on
    std::optional<MonitorSample> m_last;
    int m_samples = 0;
    QTimer m_displayChanged; // the speed display settings were read or written again
};

} // namespace opentop
