#pragma once

#include "transport/ConnectionSettings.h"

#include <QObject>
#include <QVector>
#include <functional>

class QAction;
class QMenu;
class QToolBar;

namespace opentop {

class BusDocks;
class MainWindow;

// The main window's menus (Bus, Files, Drive, View, Help) and its toolbar, and what their own
// actions do (choosing a connection, exporting the alarm histories, writing one setting to the
// selected drives). Everything else goes through the window's public side.
class MainMenus : public QObject
{
    Q_OBJECT
public:
    // `selected`: the drives selected in the bus list; `settings`: the current connection.
    MainMenus(MainWindow* window, BusDocks* docks, std::function<QVector<int>()> selected,
              std::function<ConnectionSettings()> settings);

    QToolBar* toolbar() const { return m_toolbar; }
    // The View menu (the window adds its own modes to it) and the menus that write to drives.
    QMenu* viewMenu() const { return m_view; }
    QVector<QMenu*> editingMenus() const { return m_editing; }
    // End of line: the recipe editor and the results browser (ui/eol/EolMenu fills it).
    QMenu* eolMenu() const { return m_eol; }
    // Drive > Write a setting to the selected drives (enabled while several drives of one
    // family are selected: DrivePages::sameFamilySelected).
    QAction* multiWriteAction() const { return m_multiWrite; }

private:
    void chooseConnection();
    void exportAlarms();
    void writeToSelected();

    MainWindow* m_window;
    BusDocks* m_docks;
    std::function<QVector<int>()> m_selected;
    QToolBar* m_toolbar = nullptr;
    QMenu* m_view = nullptr;
    QMenu* m_eol = nullptr;
    QVector<QMenu*> m_editing;
    QAction* m_multiWrite = nullptr;
    QAction* m_disconnect = nullptr;
};

} // namespace opentop
