#pragma once

#include "model/eol/UnitRecord.h"
#include "ui/eol/SerialEntry.h"
#include "ui/eol/StationNotice.h"
#include "ui/eol/UnitLog.h"
#include "ui/eol/VerdictLook.h"

#include <QElapsedTimer>
#include <QWidget>
#include <functional>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace opentop {

class EolSpeedChart;
class EolStation;
class ModbusClient;
class StationActions;
class StationFigures;
class StationLogin;
class TrafficLog;

// The operator screen of an end-of-line station: a large serial-number field that takes a
// barcode scanner (typing ending with Enter starts the unit), each drive's progress, the live
// speed, a PASS/FAIL panel readable from two metres with the failure in plain words, and the
// last units with this shift's counters. Nothing here edits a parameter.
class ProductionView : public QWidget
{
    Q_OBJECT
public:
    ProductionView(EolStation* station, std::function<ModbusClient*()> client, TrafficLog* traffic,
                   QWidget* parent = nullptr);

    QLineEdit* serialField() const { return m_entry->field(); }
    QLabel* verdictLabel() const { return m_verdict; }
    QLabel* reasonLabel() const { return m_reason; }
    QLabel* countersLabel() const;
    QLabel* databaseLabel() const { return m_database; }
    QLabel* noticeLabel() const { return m_notice; }
    QLabel* scanNoteLabel() const { return m_entry->scanNote(); }
    StationActions* actions() const { return m_actions; }
    StationLogin* login() const { return m_login; }
    // The station makes the recipe's drives safe on the bus the window is connected to.
    void makeSafe();
    QPushButton* cancelButton() const { return m_entry->cancelButton(); }
    QTableWidget* drivesTable() const { return m_drives; }
    QTableWidget* unitsTable() const { return m_units; }
    EolSpeedChart* chart() const { return m_chart; }
    // Opens a recipe (as the Open recipe button does, without the file dialog).
    bool openRecipe(const QString& path);
    // Shows the station's recipe, database and counters as they are now.
    void refresh();
    // Gives the serial field the keyboard, so a scanner's keys land there.
    void focusSerial();

protected:
    // The serial field takes the keys whenever the screen shows, also when the program starts
    // in production mode (a focus asked for before the window was shown does not hold).
    void showEvent(QShowEvent* event) override;

private:
    void chooseRecipe();
    void chooseUnitValues();
    void showVerdict(VerdictLook::State state, const QString& reason);
    void unitStarted(const QString& serial);
    void phaseChanged(int machineNumber, int phase, const QString& text);
    void unitFinished(const UnitRecord& record);
    void unsavedResultChanged(bool recorded);
    void showNotRecorded();
    void showVerdictOf(const UnitRecord& record, const QString& reason);
    void refreshRecipe();
    void refreshCounters();

    EolStation* m_station;
    std::function<ModbusClient*()> m_client;
    QLabel* m_recipe;
    QLabel* m_database;
    StationNotice* m_notice;
    StationLogin* m_login;
    SerialEntry* m_entry;
    QTableWidget* m_drives;
    EolSpeedChart* m_chart;
    QLabel* m_verdict;
    QLabel* m_reason;
    UnitLog* m_units;
    StationFigures* m_counters;
    StationActions* m_actions = nullptr;
    QElapsedTimer m_clock;
};

} // namespace opentop
