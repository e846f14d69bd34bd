#pragma once

#include <QObject>

class QLabel;
class QMainWindow;
class QStatusBar;

namespace opentop {

class StatusLight;
struct SerialLineReport;

// The connection in the window's status bar: the marker of a simulated bus, the link's light
// and the connection's state in one line.
class ConnectionStatus : public QObject
{
    Q_OBJECT
public:
    // Makes the widgets (children of `window`); showIn() puts them in its status bar.
    explicit ConnectionStatus(QMainWindow* window);

    void showIn(QStatusBar* bar);
    // One shortened line, red when something is wrong; the whole text in the tooltip.
    void setText(const QString& text, bool problem);
    // "Connected: DESCRIPTION — what the serial driver accepted", and the adapter's latency
    // warning in the tooltip; red when the RS-485 direction control asked for is not available.
    void setConnected(const QString& description, const SerialLineReport& report);
    // Green only while the link is up.
    void setLinkUp(bool up, const QString& why);
    void setSimulated(bool simulated);
    // No connection: grey light, no simulated marker.
    void reset();

    QLabel* label() const { return m_label; }
    StatusLight* light() const { return m_light; }
    QLabel* simulatedBanner() const { return m_simBanner; }

private:
    QLabel* m_label;
    StatusLight* m_light;
    QLabel* m_simBanner;
};

} // namespace opentop
