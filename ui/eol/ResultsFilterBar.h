#pragma once

#include "model/eol/ResultQueries.h"

#include <QWidget>

class QComboBox;
class QLineEdit;

namespace opentop {

// The results browser's bar of what to look at: the database (its address typed, or a SQLite
// file chosen) and the filters of a search (serial with wildcards, recipe, station, period,
// verdict), read as the model's ResultFilter. It only asks; the browser opens and searches.
class ResultsFilterBar : public QWidget
{
    Q_OBJECT
public:
    explicit ResultsFilterBar(QWidget* parent = nullptr);

    QString url() const;
    void setUrl(const QString& url);
    // The filters as they are now; the period counts back from now.
    ResultFilter filter() const;

    QLineEdit* serialFilter() const { return m_serial; }
    QComboBox* verdictFilter() const { return m_verdict; }
    QComboBox* periodFilter() const { return m_period; }

signals:
    // Open (or Enter in the address, or a file chosen): this database.
    void openAsked(const QString& url);
    // Search, Enter in a filter, or a period or verdict chosen.
    void searchAsked();

private:
    void chooseDatabase();

    QLineEdit* m_url = nullptr;
    QLineEdit* m_serial = nullptr;
    QLineEdit* m_recipe = nullptr;
    QLineEdit* m_station = nullptr;
    QComboBox* m_verdict = nullptr;
    QComboBox* m_period = nullptr;
};

} // namespace opentop
