#pragma once

#include "transport/ConnectionSettings.h"

#include <QObject>
#include <QVector>
#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace opentop {

class BusDrives;

// The backup, restore and compare commands of the main window's menu. Each opens its dialog;
// the dialogs do the work without blocking the window. Actions that cannot work (no drive on
// the bus, none selected) are disabled, and say why in their tooltips.
class FileActions : public QObject
{
    Q_OBJECT
public:
    FileActions(QWidget* window, QMenu* menu, std::function<BusDrives*()> drives,
                std::function<QVector<int>()> selected,
                std::function<ConnectionSettings()> connection, QObject* parent = nullptr);

    QAction* backupSelectedAction() const { return m_backupSelected; }
    QAction* backupBusAction() const { return m_backupBus; }
    QAction* openAction() const { return m_open; }
    QAction* compareAction() const { return m_compare; }
    QAction* restoreAction() const { return m_restore; }

    void updateActions();
    // The drives a backup of the whole bus reads: every identified drive.
    QVector<int> identifiedDrives() const;

private:
    void backUp(const QVector<int>& slaves);
    void openFile();
    void compare();
    void restore();

    QWidget* m_window;
    std::function<BusDrives*()> m_drives;
    std::function<QVector<int>()> m_selected;
    std::function<ConnectionSettings()> m_connection;
    QAction* m_backupSelected;
    QAction* m_backupBus;
    QAction* m_open;
    QAction* m_compare;
    QAction* m_restore;
};

} // namespace opentop
