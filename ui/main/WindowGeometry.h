#pragma once

#include <QByteArray>

class QMainWindow;
class QSplitter;

namespace opentop {

class BusPanel;

// The main window's remembered geometry, dock state and division between the bus list and the
// drive's pages (QSettings), always brought within the screen: laptop first.
class WindowGeometry
{
public:
    // `splitter`: the bus list on the left, the drive's pages on the right.
    WindowGeometry(QMainWindow* window, QSplitter* splitter);

    // The remembered geometry and dock state, or a default that fits the screen.
    void restore();
    // Divides the splitter once `panel` is in it: as remembered, or a default.
    void divide(BusPanel* panel);
    void save();

private:
    // The width that shows every column of the bus list whole, at its contents.
    static int wholeWidth(BusPanel* panel);
    // The default or remembered geometry, brought within the screen's available area.
    void fitToScreen(bool remembered);

    QMainWindow* m_window;
    QSplitter* m_splitter;
    QByteArray m_splitterState;
    bool m_userDivided = false; // the divider was moved by hand: kept where it was put
};

} // namespace opentop
