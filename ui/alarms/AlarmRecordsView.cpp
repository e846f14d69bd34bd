#include "ui/alarms/AlarmRecordsView.h"

#include "model/session/DeviceSession.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace opentop {

namespace {

enum Column
{
    ColIndex,
    ColCode,
    ColPanel,
    ColName,
    ColClearedBy,
    ColumnCount
};

} // namespace

AlarmRecordsView::AlarmRecordsView(DeviceSession* session, QWidget* parent)
    : QWidget(parent)
    , m_session(session)
    , m_detail(new QLabel)
    , m_commError(new QLabel)
{
    m_detail->setWordWrap(true);
    m_detail->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_detail->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_commError->setWordWrap(true);
    m_commError->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* layout = new QVBoxLayout(this);
    // As tight as the page around it: its minimum height decides whether the window fits.
    layout->setSpacing(3);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* tables = new QHBoxLayout;
    for (int which = 0; which < 2; ++which) {
        auto* box = new QVBoxLayout;
        m_tableLabels[which] = new QLabel;
        auto* table = new QTableWidget(0, ColumnCount);
        table->setHorizontalHeaderLabels(
            {tr("#"), tr("Code"), tr("Panel"), tr("Name"), tr("Cleared by")});
        table->setSelectionBehavior(QAbstractItemView::SelectRows);
        table->setSelectionMode(QAbstractItemView::SingleSelection);
        table->setEditTriggers(QAbstractItemView::NoEditTriggers);
        table->verticalHeader()->hide();
        table->horizontalHeader()->setSectionResizeMode(ColName, QHeaderView::Stretch);
        table->resizeColumnsToContents(); // empty: as wide as the headers, the name takes the rest
        m_tables[which] = table;
        connect(table, &QTableWidget::itemSelectionChanged, this,
                [this, which] { showDetail(which); });
        box->addWidget(m_tableLabels[which]);
        box->addWidget(table);
        tables->addLayout(box);
    }
    layout->addLayout(tables, 1);
    // Side by side: stacked, the two boxes made the page too tall for a laptop with docks open.
    auto* explanations = new QHBoxLayout;
    for (auto [title, label] : {std::pair(tr("Cause and remedy"), m_detail),
                                std::pair(tr("Communication error register"), m_commError)}) {
        auto* box = new QGroupBox(title);
        (new QVBoxLayout(box))->addWidget(label);
        explanations->addWidget(box, 1);
    }
    layout->addLayout(explanations);

    m_detail->setText(tr("Select a record to see its cause and remedy."));
    m_commError->setText(tr("Not read yet."));
}

QString AlarmRecordsView::detailText() const
{
    return m_detail->text();
}

QString AlarmRecordsView::commErrorText() const
{
    return m_commError->text();
}

const AlarmHistory::History* AlarmRecordsView::historyOf(const AlarmHistory::Report& report,
                                                         int which)
{
    const QString table = which == 0 ? QStringLiteral("alarm") : QStringLiteral("warning");
    for (const AlarmHistory::History& h : report.histories)
        if (h.table == table)
            return &h;
    return nullptr;
}

QString AlarmRecordsView::codeText(qint64 code)
{
    return QString::number(code, 16).toUpper().rightJustified(2, QLatin1Char('0')) +
           QLatin1Char('h');
}

QString AlarmRecordsView::clearedByText(const QString& reset)
{
    return CodeEntry::clearedByText(reset);
}

void AlarmRecordsView::showReport(const AlarmHistory::Report& report)
{
    m_report = report;
    for (int which = 0; which < 2; ++which)
        fillTable(which, historyOf(report, which));
    m_detail->setText(tr("Select a record to see its cause and remedy."));
    showCommError(report);
}

void AlarmRecordsView::showCommError(const AlarmHistory::Report& report)
{
    // Named by its label: users never see internal parameter names.
    const QString parameter = report.commErrorParameter.isEmpty()
                                  ? QString()
                                  : m_session->nameFor(report.commErrorParameter);
    if (parameter.isEmpty())
        m_commError->setText(tr("This drive has no communication error register."));
    else if (!report.commErrorCode)
        m_commError->setText(tr("%1: could not be read.").arg(parameter));
    else if (*report.commErrorCode == 0)
        m_commError->setText(tr("%1: no error (0).").arg(parameter));
    else if (!report.commError)
        m_commError->setText(
            tr("%1: %2, not a known code.").arg(parameter, codeText(*report.commErrorCode)));
    else
        m_commError->setText(tr("%1: %2 %3\nCause: %4\nRemedy: %5")
                                 .arg(parameter, report.commError->panel, report.commError->name,
                                      report.commError->cause, report.commError->remedy));
}

void AlarmRecordsView::fillTable(int which, const AlarmHistory::History* history)
{
    QTableWidget* table = m_tables[which];
    QLabel* label = m_tableLabels[which];
    table->clearContents();
    table->setRowCount(0);
    if (!history) {
        label->setText(which == 0 ? tr("No alarm records") : tr("No warning records"));
        table->setEnabled(false);
        return;
    }
    table->setEnabled(true);
    if (!history->ok) {
        label->setText(tr("%1: could not be read: %2").arg(history->label, history->error));
        return;
    }
    label->setText(tr("%1: %2 of %3 records, newest first")
                       .arg(history->label)
                       .arg(history->used())
                       .arg(history->records.size()));
    for (const AlarmHistory::Record& r : history->records) {
        if (r.empty)
            continue;
        const int row = table->rowCount();
        table->insertRow(row);
        const QStringList cells{QString::number(r.index), codeText(r.code),
                                r.entry ? r.entry->panel : QString(),
                                r.entry ? r.entry->name : tr("unknown code"),
                                r.entry ? clearedByText(r.entry->reset) : QString()};
        for (int c = 0; c < ColumnCount; ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setData(Qt::UserRole, r.index);
            if (c == ColIndex)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            item->setToolTip(cells[c]); // shortened in a narrow column
            table->setItem(row, c, item);
        }
    }
    table->resizeColumnsToContents();
    table->horizontalHeader()->setSectionResizeMode(ColName, QHeaderView::Stretch);
}

void AlarmRecordsView::showDetail(int which)
{
    const QList<QTableWidgetItem*> selected = m_tables[which]->selectedItems();
    if (selected.isEmpty())
        return;
    m_tables[1 - which]->clearSelection();
    const int index = selected.first()->data(Qt::UserRole).toInt();
    const AlarmHistory::History* history = historyOf(m_report, which);
    if (!history)
        return;
    for (const AlarmHistory::Record& r : history->records) {
        if (r.index != index)
            continue;
        if (!r.entry) {
            m_detail->setText(tr("Record %1: code %2 is not in the %3 table.")
                                  .arg(r.index)
                                  .arg(codeText(r.code), history->label));
            return;
        }
        QStringList lines{tr("%1 %2 (record %3)").arg(r.entry->panel, r.entry->name).arg(r.index)};
        if (!r.entry->cause.isEmpty())
            lines << tr("Cause: %1").arg(r.entry->cause);
        if (!r.entry->remedy.isEmpty())
            lines << tr("Remedy: %1").arg(r.entry->remedy);
        if (!r.entry->resetText.isEmpty())
            lines << tr("To clear: %1").arg(r.entry->resetText);
        m_detail->setText(lines.join(QLatin1Char('\n')));
        return;
    }
}

} // namespace opentop
