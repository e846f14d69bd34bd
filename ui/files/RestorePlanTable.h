#pragma once

#include "model/files/RestorePlan.h"

#include <QTableWidget>

class QCheckBox;

namespace opentop {

// The items of restore plans, one row each: what a preview would do (changes highlighted) or,
// after writing, what happened (failures and values read back differently in red); optionally
// the differences only.
class RestorePlanTable : public QTableWidget
{
    Q_OBJECT
public:
    enum Column
    {
        Drive,
        Parameter,
        Action,
        FileValue,
        DriveValue,
        Result,
        ColumnCount
    };

    explicit RestorePlanTable(QWidget* parent = nullptr);

    void showPlans(const QVector<RestorePlan>& plans, bool written);
    // Only the rows that change something or went wrong: a setting the drive already holds
    // (kept, unchanged) is hidden.
    void setDifferencesOnly(bool only);
    bool differencesOnly() const { return m_differencesOnly; }
    // Rows not hidden by the filter.
    int shownRows() const;
    // The table below its "Differences only" box, for a dialog to lay out (made once).
    QWidget* withFilter();
    QCheckBox* filterBox() const { return m_filterBox; }
    QString cellText(int slave, const QString& parameter, Column column) const;
    bool isFailureHighlighted(int slave, const QString& parameter) const;

    static QColor changeColor();
    static QColor failureColor();

private:
    int rowOf(int slave, const QString& parameter) const;
    void applyFilter();

    bool m_differencesOnly = false;
    QCheckBox* m_filterBox = nullptr;
};

} // namespace opentop
