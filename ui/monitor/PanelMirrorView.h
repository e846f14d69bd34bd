#pragma once

#include "model/monitor/PanelMirror.h"

#include <QTimer>
#include <QWidget>
#include <optional>

class QLabel;

namespace opentop {

class StatusLight;

// A drive's own 5-digit panel and MONITOR LED, mirrored: the characters the panel shows in
// the drive's display mode, red and flashing while an alarm is active, with what they mean
// written beside them (the panel alone is cryptic: "LD015").
class PanelMirrorView : public QWidget
{
    Q_OBJECT
public:
    explicit PanelMirrorView(QWidget* parent = nullptr);

    void setShown(const PanelMirror::Shown& shown, const QString& contentName);
    StatusLight* light() const { return m_light; }
    // No longer live (monitor/Freshness): the digits grey and steady, the LED grey.
    void setStale(bool stale, const QString& why = QString());
    bool isStale() const { return m_stale; }
    QString panelText() const { return m_shown.text; }
    QString meaningText() const;

private:
    void paintPanel();

    QLabel* m_panel;
    QLabel* m_meaning;
    QLabel* m_content;
    StatusLight* m_light;
    PanelMirror::Shown m_shown;
    QTimer m_blink;
    bool m_blinkOn = true;
    std::optional<bool> m_lit; // the style applied
    bool m_stale = false;
};

} // namespace opentop
