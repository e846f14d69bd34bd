#pragma once

#include <QObject>
#include <QVector>
#include <functional>

class QAction;
class QBoxLayout;
class QDockWidget;
class QMainWindow;
class QMenu;

namespace opentop {

class EolStation;
class ModbusClient;
class ProductionView;
class TrafficLog;

// Switches the main window between engineering mode (drives, pages, docks: parameter editing)
// and production mode (the end-of-line operator screen, ProductionView, and nothing that
// edits a parameter; STOP ALL stays). Also what the window asks before it quits, disconnects
// or connects elsewhere while a unit is being tested.
class ProductionMode : public QObject
{
    Q_OBJECT
public:
    // `engineering`: what production mode hides (the drive panel and pages); the operator screen
    // goes into `column` beside it. `editingMenus`: menus that write to drives, disabled while
    // in production mode.
    ProductionMode(QMainWindow* window, QWidget* engineering, QBoxLayout* column,
                   QVector<QMenu*> editingMenus, std::function<ModbusClient*()> client,
                   TrafficLog* traffic);

    QAction* toggleAction() const { return m_toggle; }
    QAction* fullScreenAction() const { return m_fullScreen; }
    QAction* stationNameAction() const { return m_stationName; }
    bool isActive() const;
    void setActive(bool active);
    EolStation* station() const { return m_station; }
    ProductionView* view() const { return m_view; }

    // While a unit is being tested: asks whether to cancel it (its motors are stopped first)
    // to `what` ("quit"), and runs `then` once it has ended. Returns false, and does nothing,
    // when no unit is being tested.
    bool guard(const QString& what, std::function<void()> then);

private:
    void askStationName();
    QMainWindow* m_window;
    QWidget* m_engineering;
    QVector<QMenu*> m_editingMenus;
    EolStation* m_station;
    ProductionView* m_view;
    QAction* m_toggle;
    QAction* m_fullScreen;
    QAction* m_stationName;
    QVector<QDockWidget*> m_hiddenDocks;
    bool m_warnedDatabase = false; // the operator was told the database cannot be reached
    bool m_leaving = false;        // leaving was allowed (IdentityDialog)
};

} // namespace opentop
