#pragma once

#include <QObject>

class QWidget;

namespace opentop {

// Keeps a window the menus open (compare, restore, the recipe editor…) clear of the main
// window's STOP ALL button: a window centred on a 1366×700 laptop's main window covered it, and
// STOP ALL must stay one click away whatever is open. When shown, the window moves beside the
// button (below, above, right or left, where it fits), and shrinks only if it fits nowhere.
class ClearOfStopAll : public QObject
{
    Q_OBJECT
public:
    // Watches `window` (a top-level widget with the main window as its parent).
    static void keep(QWidget* window);

    // Moves `window` clear of STOP ALL now; whether it had to.
    static bool place(QWidget* window);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    using QObject::QObject;
};

} // namespace opentop
