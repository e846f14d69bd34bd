#pragma once

#include "model/session/DeviceInfo.h"

#include <QVector>
#include <QWidget>

class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableView;

namespace opentop {

class BusDrives;
class BusListMenu;
class BusListModel;
class BusScanner;
class DeviceIdentifier;
class DriveStatusPoller;

// The left side of the main window: finds the drives on the bus (Scan over a machine number
// range, or Add drive by number) and lists them with their status light, machine number and
// switch positions, identity, communication state and control priority. Everything found goes
// into BusDrives; the list follows BusDrives and the poller. Drives whose variant the bus does
// not tell get a Variant choice in the context menu; every machine can be named (F2).
class BusPanel : public QWidget
{
    Q_OBJECT
public:
    BusPanel(BusDrives* drives, DriveStatusPoller* poller, QWidget* parent = nullptr);
    ~BusPanel() override;

    // Asks machine numbers from..to; drives appear in the list as they are found. Polling
    // waits meanwhile (the scanner holds the bus), and the message says so.
    void startScan(int from, int to);
    bool isScanning() const;
    // Stops between transactions; the message says how far the scan got.
    void cancelScan();
    // Identifies one machine number and adds it to the list (also when nobody answers).
    void addDrive(int slave);

    QVector<int> selectedSlaves() const;
    QTableView* view() const { return m_view; }
    BusListModel* model() const { return m_model; }
    QProgressBar* progressBar() const { return m_progress; }
    // The last scan or add result for people ("3 drives found in 1.2 s").
    QString message() const;
    // Shown after a scan that found nothing, when the line is not at the DC controller's fixed
    // potentiometer-mode settings (FixedLineHint): asks for a rescan at them.
    QPushButton* fixedLineButton() const { return m_fixedLine; }
    // The context menu for `slaves` (BusListMenu; the caller owns it); public for tests.
    QMenu* contextMenuFor(const QVector<int>& slaves, QWidget* parent);

signals:
    void selectionChanged(const QVector<int>& slaves);
    void scanFinished();
    void driveAddedByNumber(int slave); // identification of addDrive() finished
    // The user asks to reconnect at FixedLineHint's settings and scan its address; the main
    // window owns the connection and does it.
    void fixedLineRescanRequested();

private:
    void scanClicked();
    void addClicked();
    void onScanFinished();
    void syncDrive(int slave);
    void showMessage(const QString& text, bool problem = false);
    void updateButtons();
    void fitNameColumn();
    void showContextMenu(const QPoint& pos);

    BusDrives* m_drives;
    DriveStatusPoller* m_poller;
    BusListModel* m_model;
    BusScanner* m_scanner = nullptr;
    QPushButton* m_fixedLine = nullptr;
    DeviceIdentifier* m_identifier;
    QPushButton* m_scan;
    QSpinBox* m_from;
    QSpinBox* m_to;
    QPushButton* m_add;
    QProgressBar* m_progress;
    QPushButton* m_cancel;
    QLabel* m_message;
    QTableView* m_view;
    BusListMenu* m_menu;
    int m_adding = 0;
};

} // namespace opentop
