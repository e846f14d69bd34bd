#include "ui/eol/UnitLog.h"

#include "model/io/DisplayText.h"

#include <QHeaderView>

namespace opentop {

namespace {

constexpr int kVerdictColumn = 2;
constexpr int kMaxRows = 50;

} // namespace

UnitLog::UnitLog(QWidget* parent)
    : QTableWidget(0, 4, parent)
{
    setHorizontalHeaderLabels({tr("Time"), tr("Serial"), tr("Verdict"), tr("Reason")});
    horizontalHeader()->setStretchLastSection(true);
    verticalHeader()->hide();
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionMode(QAbstractItemView::NoSelection);
    setFocusPolicy(Qt::NoFocus); // the serial field keeps the scanner's keys
}

void UnitLog::add(const UnitRecord& record, Kept kept)
{
    insertRow(0);
    QString verdict = unitStatusName(record.status).toUpper();
    if (kept == Kept::NotRecorded)
        verdict = tr("%1, NOT RECORDED").arg(verdict);
    else if (kept == Kept::OnStation)
        verdict = tr("%1 (kept on this station)").arg(verdict);
    const QStringList cells{record.ended.toLocalTime().toString(QStringLiteral("HH:mm:ss")),
                            record.serial, verdict, record.failureReason};
    for (int c = 0; c < cells.size(); ++c)
        setItem(0, c, new QTableWidgetItem(DisplayText::escaped(cells[c])));
    if (rowCount() > kMaxRows)
        removeRow(rowCount() - 1);
}

void UnitLog::markRecorded(UnitStatus status)
{
    if (rowCount() > 0 && item(0, kVerdictColumn))
        item(0, kVerdictColumn)->setText(unitStatusName(status).toUpper());
}

} // namespace opentop
