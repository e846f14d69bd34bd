#pragma once

#include <QHash>
#include <QMainWindow>
#include <QVector>

class QLabel;
class QTableView;

namespace opentop {

class BusListModel;
class DeviceIdentifier;
class ModbusClient;
struct DeviceInfo;

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
    // Variants the user (or the simulated bus list) says are at these machine numbers; used
    // where a drive does not report its variant.
    void setAssignedTypes(const QHash<int, QString>& types) { m_assignedTypes = types; }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void onOpened(bool ok, const QString& error);
    void identifyAll();
    void applyAssignedVariant(DeviceInfo* info) const;

    ModbusClient* m_client;
    QVector<int> m_expected;
    QHash<int, QString> m_assignedTypes;
    BusListModel* m_model;
    DeviceIdentifier* m_identifier;
    QTableView* m_table;
    QLabel* m_connectionLabel;
    int m_outstanding = 0;
};

} // namespace opentop
