#pragma once

#include <QMainWindow>
#include <QVector>

class QLabel;
class QTableView;

namespace opentop {

class BusListModel;
class DeviceIdentifier;
class ModbusClient;

// The main window: the drives on the bus. It owns no bus logic; the client and identifier do
// the talking, asynchronously.
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    // `expected`: machine numbers to identify once connected (the simulated bus's devices).
    MainWindow(ModbusClient* client, const QVector<int>& expected, QWidget* parent = nullptr);
    ~MainWindow() override;

    BusListModel* busModel() const { return m_model; }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void onOpened(bool ok, const QString& error);
    void identifyAll();

    ModbusClient* m_client;
    QVector<int> m_expected;
    BusListModel* m_model;
    DeviceIdentifier* m_identifier;
    QTableView* m_table;
    QLabel* m_connectionLabel;
    int m_outstanding = 0;
};

} // namespace opentop
