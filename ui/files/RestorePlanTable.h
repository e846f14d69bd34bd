#pragma once

#include "files/RestorePlan.h"

#include <QTableWidget>

namespace opentop {

// The items of restore plans, one row each: what a preview would do (changes highlighted) or,
// after writing, what happened (failures and values read back differently in red).
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
    QString cellText(int slave, const QString& parameter, Column column) const;
    bool isFailureHighlighted(int slave, const QString& parameter) const;

    static QColor changeColor();
    static QColor failureColor();

private:
    int rowOf(int slave, const QString& parameter) const;
};

} // namespace opentop
