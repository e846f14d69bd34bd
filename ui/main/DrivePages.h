#pragma once

#include <QObject>
#include <QVector>

namespace opentop {

class AlarmsPage;
class MainWindow;

// The selected drive's pages in the window's workspace: its settings, and the monitoring side
// (Monitor first, Test run, Alarms). Follows the bus list's selection; works through the
// window's public side, so it only acts while connected.
class DrivePages : public QObject
{
    Q_OBJECT
public:
    explicit DrivePages(MainWindow* window);

    // The drives selected in the bus list.
    const QVector<int>& selected() const { return m_selected; }
    // Opens the pages of the first of `slaves` (the bus list's selection).
    void showDrive(const QVector<int>& slaves);
    // Selects `slave` and brings its Alarms page to the front (the alarm banner's Show).
    void showAlarmsOf(int slave);
    // The selected drive's Alarms page (null when none is open).
    AlarmsPage* alarmsPage() const;
    // The header follows a drive's change (its variant identified or set by hand).
    void retitle(int slave);
    // Closes every page (before the drives they use are gone).
    void clear();

signals:
    // Several drives of one family are selected (or no longer): one setting can be written to
    // all of them.
    void sameFamilySelected(bool yes);

private:
    QString driveTitle(int slave) const;

    MainWindow* m_window;
    QVector<int> m_selected;
};

} // namespace opentop
