#pragma once

#include "eol/UnitRecord.h"
#include "eol/YieldReport.h"

#include <QDialog>
#include <QVector>
#include <memory>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;
class QTextBrowser;

namespace opentop {

class ResultDatabase;

// The engineers' view of the results database: units found by serial, period, recipe, station
// and verdict, the first-pass yield of what was found, one unit's whole record (what its
// certificate says), CSV export and the unit's certificate as PDF. Queries run on the UI thread:
// they read indexed rows of one database and take milliseconds (docs/eol-results.md).
class ResultsBrowser : public QDialog
{
    Q_OBJECT
public:
    // `url`: the database to open (empty: OPENTOP_EOL_DB, else the default file).
    explicit ResultsBrowser(const QString& url, QWidget* parent = nullptr);
    ~ResultsBrowser() override;

    // Opens a database; false, said in the window, when it cannot be opened or a SQLite file
    // does not exist (the browser never creates one).
    bool openDatabase(const QString& url);
    // Runs the filters; false (said in the window) on a database error.
    bool search();
    const QVector<UnitRecord>& units() const { return m_units; }
    QString summary() const;
    bool exportCsv(const QString& path, QString* error) const;
    // The selected unit's certificate; false with *error when none is selected or on an error.
    bool saveCertificate(const QString& path, QString* error);

    QLineEdit* serialFilter() const { return m_serial; }
    QComboBox* verdictFilter() const { return m_verdict; }
    QComboBox* periodFilter() const { return m_period; }
    QTableWidget* table() const { return m_table; }
    QTextBrowser* details() const { return m_details; }

private:
    QWidget* makeFilters();
    void showSelected();
    void chooseDatabase();
    void chooseCsv();
    void chooseCertificate();
    void say(const QString& text, bool error);
    std::optional<UnitRecord> selectedRecord(QString* error);

    std::unique_ptr<ResultDatabase> m_db;
    QVector<UnitRecord> m_units;
    YieldReport::Earlier m_earlier; // serials of the period tested before it
    QLineEdit* m_url = nullptr;
    QLineEdit* m_serial = nullptr;
    QLineEdit* m_recipe = nullptr;
    QLineEdit* m_station = nullptr;
    QComboBox* m_verdict = nullptr;
    QComboBox* m_period = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_message = nullptr;
    QTableWidget* m_table = nullptr;
    QTextBrowser* m_details = nullptr;
    QPushButton* m_csv = nullptr;
    QPushButton* m_certificate = nullptr;
};

} // namespace opentop
