#include "ui/files/RestorePlanTable.h"

#include <QCheckBox>
#include <QHeaderView>
#include <QVBoxLayout>

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
            // What the filter keeps: anything sent or to send, and anything that went wrong.
            const bool difference =
                item.action != Item::Action::Keep || item.mismatch ||
                (item.status != Item::Status::Unchanged && item.status != Item::Status::Pending);
            for (int c = 0; c < ColumnCount; ++c) {
                auto* cell = new QTableWidgetItem(cells.at(c));
                if (c == 0)
                    cell->setData(Qt::UserRole, difference);
                if (background.isValid()) {
                    cell->setBackground(background);
                    cell->setForeground(QColor(Qt::black));
                }
                setItem(row, c, cell);
            }
        }
    }
    applyFilter();
    resizeColumnsToContents();
}

void RestorePlanTable::setDifferencesOnly(bool only)
{
    m_differencesOnly = only;
    applyFilter();
}

void RestorePlanTable::applyFilter()
{
    for (int row = 0; row < rowCount(); ++row)
        setRowHidden(row, m_differencesOnly && !item(row, Drive)->data(Qt::UserRole).toBool());
}

QWidget* RestorePlanTable::withFilter()
{
    // A drive holds most of a file's settings already; the few that change are what one checks
    // before writing.
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    m_filterBox = new QCheckBox(tr("&Differences only"), box);
    m_filterBox->setToolTip(
        tr("Show only the settings that would be written (or were), and what went wrong"));
    connect(m_filterBox, &QCheckBox::toggled, this, &RestorePlanTable::setDifferencesOnly);
    layout->addWidget(m_filterBox);
    layout->addWidget(this, 1);
    return box;
}

int RestorePlanTable::shownRows() const
{
    int shown = 0;
    for (int row = 0; row < rowCount(); ++row)
        shown += isRowHidden(row) ? 0 : 1;
    return shown;
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
