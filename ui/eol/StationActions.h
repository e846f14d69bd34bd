#pragma once

#include "model/eol/UnitRecord.h"

#include <QWidget>
#include <functional>

class QLabel;
class QPushButton;

namespace opentop {

class EolStation;
class ModbusClient;

// What an operator can do about a unit the station could not test, under the verdict: reset an
// alarm latched before the test and test the unit again, or have a technician allow a retest
// the recipe's rules hold back. Hidden when there is nothing to do.
class StationActions : public QWidget
{
    Q_OBJECT
public:
    // `operatorName`: who is at the screen, named as allowing a retest that needs a technician
    // (a station without users: the person at the screen is asked and named).
    StationActions(EolStation* station, std::function<ModbusClient*()> client,
                   std::function<QString()> operatorName, QWidget* parent = nullptr);

    QPushButton* resetButton() const { return m_reset; }
    QPushButton* retestButton() const { return m_retest; }
    QLabel* textLabel() const { return m_text; }

private:
    void unitFinished(const UnitRecord& record);
    void show(const QString& text, QPushButton* button);
    void clear();
    QString whoAllows(); // a station without users: the person at the screen, asked
    void resetAlarms();
    void retestBy(const QString& by); // empty: nobody allowed it, nothing is started

    EolStation* m_station;
    std::function<ModbusClient*()> m_client;
    std::function<QString()> m_operatorName;
    QLabel* m_text;
    QPushButton* m_reset;
    QPushButton* m_retest;
    QString m_retestSerial;
    QString m_retestWhy;
};

} // namespace opentop
