#pragma once

#include <QObject>

class QAction;
class QMainWindow;
class QMenu;

namespace opentop {

// The Help menu: the user guide, the keyboard shortcuts and About. The dialogs show beside the
// window (not modal), one of each at a time.
class HelpActions : public QObject
{
    Q_OBJECT
public:
    HelpActions(QMainWindow* window, QMenu* menu);

    QAction* guideAction() const { return m_guide; }
    QAction* shortcutsAction() const { return m_shortcuts; }
    QAction* aboutAction() const { return m_about; }

private:
    template <typename Dialog, typename... Args> void showOnce(const char* name, Args... args);

    QMainWindow* m_window;
    QAction* m_guide;
    QAction* m_shortcuts;
    QAction* m_about;
};

} // namespace opentop
