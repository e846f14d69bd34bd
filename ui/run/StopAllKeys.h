#pragma once

#include <QObject>
#include <functional>

class QKeyEvent;

namespace opentop {

class StopAllButton;

// Pause and Ctrl+Shift+S press STOP ALL from anywhere in the application: the main window, a
// non-modal result window and modal dialogs alike. A QShortcut cannot do that (a modal dialog
// blocks the shortcuts of the window behind it), so this filters the application's key events
// before any widget or shortcut sees them.
class StopAllKeys : public QObject
{
    Q_OBJECT
public:
    // `button` is asked at each press (the window may rebuild its button on a reconnection);
    // the filter lives as long as `owner`.
    StopAllKeys(std::function<StopAllButton*()> button, QObject* owner);
    ~StopAllKeys() override;

    // Whether `event` is one of StopAllButton::shortcuts().
    static bool matches(const QKeyEvent* event);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    std::function<StopAllButton*()> m_button;
};

} // namespace opentop
