#pragma once

#include "model/eol/UnitRecord.h"
#include "model/eol/YieldReport.h"
#include "ui/eol/ResultsFilterBar.h"

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

class ResultWriter;

// The engineers' view of the results database: units found by serial, period, recipe, station
// and verdict, the first-pass yield of what was found, one unit's whole record (what its
// certificate says), CSV export and the unit's certificate as PDF. The database is opened and
// queried on a thread of its own (ResultWriter): a factory's PostgreSQL server may be slow to
// answer, and the window must not stand still meanwhile.
class ResultsBrowser : public QDialog
{
    Q_OBJECT
public:
    // `url`: the database to open (empty: OPENTOP_EOL_DB, else the default file).
    explicit ResultsBrowser(const QString& url, QWidget* parent = nullptr);
    ~ResultsBrowser() override;

    // Opens a database, then searches with the filters; false, said in the window, when the
    // address is not usable or a SQLite file does not exist (the browser never creates one);
    // one that cannot be opened is said when its answer comes (searched(false)).
    bool openDatabase(const QString& url);
    // Runs the filters; false when no database is open. searched() answers.
    bool search();
    // A database is being opened or queried.
    bool isBusy() const;
    const QVector<UnitRecord>& units() const { return m_units; }
    QString summary() const;
    bool exportCsv(const QString& path, QString* error) const;
    // The selected unit's certificate; false with *error when none is selected, its record is
    // still being read, or on an error.
    bool saveCertificate(const QString& path, QString* error);

    QLineEdit* serialFilter() const { return m_filters->serialFilter(); }
    QComboBox* verdictFilter() const { return m_filters->verdictFilter(); }
    QComboBox* periodFilter() const { return m_filters->periodFilter(); }
    QTableWidget* table() const { return m_table; }
    QTextBrowser* details() const { return m_details; }

signals:
    // A search (or the open before it) has answered; false: said in the window.
    void searched(bool ok);
    // The selected unit's record is shown (or why not).
    void detailsShown();

private:
    void showFound(const YieldReport::Tables& tables);
    void showSelected();
    void chooseCsv();
    void chooseCertificate();
    void say(const QString& text, bool error);

    std::unique_ptr<ResultWriter> m_results;
    bool m_open = false;
    int m_generation = 0; // answers for an earlier database or search are dropped
    QVector<UnitRecord> m_units;
    std::optional<UnitRecord> m_selected;  // the selected unit's whole record, once read
    QVector<UnitRecord> m_selectedEarlier; // its serial's records before it
    YieldRow m_yield;                      // the period's, over every recipe found
    ResultsFilterBar* m_filters = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_message = nullptr;
    QTableWidget* m_table = nullptr;
    QTextBrowser* m_details = nullptr;
    QPushButton* m_csv = nullptr;
    QPushButton* m_certificate = nullptr;
};

} // namespace opentop
