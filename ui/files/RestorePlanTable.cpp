#include "files/RestorePlanTable.h"

#include <QHeaderView>

namespace opentop {

using Item = RestorePlan::Item;

RestorePlanTable::RestorePlanTable(QWidget* parent)
    : QTableWidget(0, ColumnCount, parent)
{
    setHorizontalHeaderLabels({tr("Drive"), tr("Parameter"), tr("Action"), tr("File value"),
                               tr("Drive value before"), tr("Result")});
    verticalHeader()->hide();
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    horizontalHeader()->setStretchLastSection(true);
    resizeColumnsToContents(); // before a plan is shown: the headers readable
}

QColor RestorePlanTable::changeColor()
{
    return QColor(255, 214, 153);
}

QColor RestorePlanTable::failureColor()
{
    return QColor(255, 170, 170);
}

void RestorePlanTable::showPlans(const QVector<RestorePlan>& plans, bool written)
{
    setRowCount(0);
    for (const RestorePlan& plan : plans) {
        for (const Item& item : plan.items) {
            const int row = rowCount();
            insertRow(row);
            const bool store = item.action == Item::Action::Store;
            const QStringList cells{QString::number(plan.slave),
                                    item.parameter,
                                    RestorePlan::actionText(item.action),
                                    store ? QString() : item.fileText,
                                    store ? QString() : item.deviceText,
                                    written ? RestorePlan::statusText(item) : QString()};
            // Black text on the light colours so that a dark theme stays readable.
            QColor background;
            if (item.mismatch || item.status == Item::Status::Failed ||
                item.status == Item::Status::NotConfirmed)
                background = failureColor();
            else if (item.action == Item::Action::Write)
                background = changeColor();
            for (int c = 0; c < ColumnCount; ++c) {
                auto* cell = new QTableWidgetItem(cells.at(c));
                if (background.isValid()) {
                    cell->setBackground(background);
                    cell->setForeground(QColor(Qt::black));
                }
                setItem(row, c, cell);
            }
        }
    }
    resizeColumnsToContents();
}

int RestorePlanTable::rowOf(int slave, const QString& parameter) const
{
    for (int row = 0; row < rowCount(); ++row) {
        if (item(row, Drive)->text().toInt() == slave && item(row, Parameter)->text() == parameter)
            return row;
    }
    return -1;
}

QString RestorePlanTable::cellText(int slave, const QString& parameter, Column column) const
{
    const int row = rowOf(slave, parameter);
    return row >= 0 ? item(row, column)->text() : QString();
}

bool RestorePlanTable::isFailureHighlighted(int slave, const QString& parameter) const
{
    const int row = rowOf(slave, parameter);
    return row >= 0 && item(row, Result)->background().color() == failureColor();
}

} // namespace opentop
