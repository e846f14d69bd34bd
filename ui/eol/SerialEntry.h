#pragma once

#include <QWidget>
#include <functional>

class QLabel;
class QLineEdit;
class QPushButton;

namespace opentop {

class EolStation;
class ModbusClient;
class TrafficLog;

// The operator screen's entry row: the large serial-number field a barcode scanner types into
// (Enter starts the unit, after the per-unit values the recipe leaves to the operator, each
// asked within its range), Cancel unit, and under them the note that refuses a serial scanned
// while another unit is tested: refused where the operator looks, never dropped.
class SerialEntry : public QWidget
{
    Q_OBJECT
public:
    SerialEntry(EolStation* station, std::function<ModbusClient*()> client, TrafficLog* traffic,
                QWidget* parent = nullptr);

    QLineEdit* field() const { return m_serial; }
    QPushButton* cancelButton() const { return m_cancel; }
    QLabel* scanNote() const { return m_scanNote; }
    // A unit began: Cancel on, an earlier refusal gone, the field cleared but left open (a
    // serial scanned now is refused aloud).
    void unitStarted();

signals:
    // The station did not take the unit: why.
    void notStarted(const QString& why);
    // The station takes the unit once its drives are safe.
    void waitingForSafety(const QString& serial);

private:
    void start();
    void refuseWhileTesting(const QString& serial);
    // Asks the values the recipe leaves to the operator; false when one was not given.
    bool askOperatorValues(QHash<int, QHash<QString, double>>* typed);

    EolStation* m_station;
    std::function<ModbusClient*()> m_client;
    TrafficLog* m_traffic;
    QLineEdit* m_serial;
    QPushButton* m_cancel;
    QLabel* m_scanNote;
};

} // namespace opentop
