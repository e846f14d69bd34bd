#pragma once

#include <QObject>
#include <QPointer>
#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace opentop {

class BusDrives;
class StationAccess;

// The End of line menu's engineering tools: the recipe editor and the results browser, one
// window each, kept while the program runs (a second choice brings the window back).
class EolMenu : public QObject
{
    Q_OBJECT
public:
    EolMenu(QMenu* menu, QWidget* window, std::function<BusDrives*()> drives);

    QAction* recipeEditorAction() const { return m_editor; }
    QAction* resultsAction() const { return m_results; }
    // The station's users: on a managed station the recipe editor asks for an engineer.
    void setAccess(StationAccess* access);

private:
    QWidget* m_window;
    std::function<BusDrives*()> m_drives;
    QAction* m_editor = nullptr;
    QAction* m_results = nullptr;
    QPointer<StationAccess> m_access;
};

} // namespace opentop
