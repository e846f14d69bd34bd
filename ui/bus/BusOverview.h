#pragma once

#include <QWidget>

class QLabel;
class QTableView;

namespace opentop {

class BusDrives;
class BusOverviewModel;
class MonitorHub;

// The bus overview: every drive in one live grid (BusOverviewModel). Monitors every drive
// while it is shown, and none while it is hidden, so that a closed overview costs no traffic.
class BusOverview : public QWidget
{
    Q_OBJECT
public:
    BusOverview(BusDrives* drives, MonitorHub* hub, QWidget* parent = nullptr);

    BusOverviewModel* model() const { return m_model; }
    QTableView* view() const { return m_view; }

signals:
    // Double-click: the user wants this drive's pages.
    void driveActivated(int slave);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void watchAll();

    BusDrives* m_drives;
    MonitorHub* m_hub;
    BusOverviewModel* m_model;
    QTableView* m_view;
    bool m_watching = false;
    bool m_sized = false; // columns fitted to the first values
};

} // namespace opentop
