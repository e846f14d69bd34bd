#include "ui/traffic/TrafficLogView.h"

#include "model/io/OutputFile.h"
#include "transport/TrafficLog.h"
#include "ui/traffic/TrafficLogFilter.h"
#include "ui/traffic/TrafficLogModel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace opentop {

namespace {

QTableWidgetItem* cell(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

} // namespace

TrafficLogView::TrafficLogView(TrafficLog* log, QWidget* parent)
    : QWidget(parent)
    , m_log(log)
    , m_model(new TrafficLogModel(log ? log->capacity() : 20000, this))
    , m_filter(new TrafficLogFilter(this))
    , m_drive(new QComboBox(this))
    , m_direction(new QComboBox(this))
    , m_errorsOnly(new QCheckBox(tr("&Errors only"), this))
    , m_pause(new QPushButton(tr("&Pause"), this))
    , m_table(new QTableView(this))
    , m_stats(new QTableWidget(this))
    , m_refresh(new QTimer(this))
    , m_take(new QTimer(this))
{
    m_filter->setSourceModel(m_model);

    m_drive->setObjectName(QStringLiteral("trafficDrive"));
    m_drive->addItem(tr("All drives"), -1);
    m_direction->setObjectName(QStringLiteral("trafficDirection"));
    m_direction->addItem(tr("All"), int(TrafficLogFilter::DirectionFilter::All));
    m_direction->addItem(tr("Tx (requests)"), int(TrafficLogFilter::DirectionFilter::Tx));
    m_direction->addItem(tr("Rx (replies)"), int(TrafficLogFilter::DirectionFilter::Rx));
    m_direction->addItem(tr("Events (no reply)"), int(TrafficLogFilter::DirectionFilter::Events));
    m_errorsOnly->setObjectName(QStringLiteral("trafficErrorsOnly"));
    m_pause->setObjectName(QStringLiteral("trafficPause"));
    m_pause->setCheckable(true);
    auto* clearButton = new QPushButton(tr("&Clear"), this);
    clearButton->setObjectName(QStringLiteral("trafficClear"));
    auto* saveButton = new QPushButton(tr("&Save…"), this);
    saveButton->setObjectName(QStringLiteral("trafficSave"));

    auto* driveLabel = new QLabel(tr("&Drive:"), this);
    driveLabel->setBuddy(m_drive);
    auto* directionLabel = new QLabel(tr("Di&rection:"), this);
    directionLabel->setBuddy(m_direction);
    auto* bar = new QHBoxLayout;
    bar->addWidget(driveLabel);
    bar->addWidget(m_drive);
    bar->addWidget(directionLabel);
    bar->addWidget(m_direction);
    bar->addWidget(m_errorsOnly);
    bar->addStretch();
    bar->addWidget(m_pause);
    bar->addWidget(clearButton);
    bar->addWidget(saveButton);

    m_table->setObjectName(QStringLiteral("trafficTable"));
    m_table->setAccessibleName(tr("Frames"));
    m_table->setModel(m_filter);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->horizontalHeader()->setStretchLastSection(true);
    // Short columns as wide as their header or contents; the meaning takes what is left (the
    // whole line of a row is its tooltip).
    const QFontMetrics metrics = m_table->fontMetrics();
    const std::pair<int, QString> samples[] = {
        {TrafficLogModel::Time, QStringLiteral("00:00:00.000")},
        {TrafficLogModel::Direction, QStringLiteral("Tx")},
        {TrafficLogModel::Slave, QStringLiteral("247")},
        {TrafficLogModel::Function, QStringLiteral("83")}};
    for (const auto& [column, sample] : samples) {
        m_table->setColumnWidth(column,
                                std::max(m_table->horizontalHeader()->sectionSizeHint(column),
                                         metrics.horizontalAdvance(sample) + 16));
    }
    m_table->setColumnWidth(TrafficLogModel::Bytes,
                            metrics.horizontalAdvance(QLatin1Char('0')) * 27);
    m_table->setColumnWidth(TrafficLogModel::Error,
                            metrics.horizontalAdvance(QLatin1Char('x')) * 18);
    m_table->setTextElideMode(Qt::ElideRight);

    const QStringList statsHeaders = {
        tr("Drive"),      tr("Requests"),      tr("Replies"),      tr("Timeouts"), tr("CRC errors"),
        tr("Exceptions"), tr("Wrong/garbled"), tr("Late replies"), tr("Mean ms"),  tr("Max ms")};
    m_stats->setObjectName(QStringLiteral("trafficStatistics"));
    m_stats->setAccessibleName(tr("Statistics per drive"));
    m_stats->setColumnCount(int(statsHeaders.size()));
    m_stats->setHorizontalHeaderLabels(statsHeaders);
    m_stats->horizontalHeaderItem(7)->setToolTip(
        tr("Frames that answered nothing asked at the time: a reply to an earlier request "
           "that came too late, discarded and never taken as a value"));
    m_stats->verticalHeader()->hide();
    m_stats->setEditTriggers(QAbstractItemView::NoEditTriggers);
    // Its header and a row at least, not a scroll bar's height: with every dock open on a
    // laptop (and CJK rows taller) the window must still fit the screen.
    m_stats->setMinimumHeight(m_stats->horizontalHeader()->sizeHint().height() +
                              2 * m_stats->frameWidth() + m_stats->fontMetrics().height() + 8);

    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_table);
    splitter->addWidget(m_stats);
    splitter->setStretchFactor(0, 4);
    splitter->setStretchFactor(1, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(splitter);

    m_refresh->setSingleShot(true);
    m_refresh->setInterval(200);
    connect(m_refresh, &QTimer::timeout, this, &TrafficLogView::refresh);
    connect(m_drive, qOverload<int>(&QComboBox::currentIndexChanged), this,
            &TrafficLogView::applyFilters);
    connect(m_direction, qOverload<int>(&QComboBox::currentIndexChanged), this,
            &TrafficLogView::applyFilters);
    connect(m_errorsOnly, &QCheckBox::toggled, this, &TrafficLogView::applyFilters);
    connect(m_pause, &QPushButton::toggled, this, &TrafficLogView::setPaused);
    connect(clearButton, &QPushButton::clicked, this, &TrafficLogView::clear);
    connect(saveButton, &QPushButton::clicked, this, &TrafficLogView::save);
    if (m_log) {
        // New frames are taken from the log ten times a second rather than signalled one by
        // one: the bus thread then never wakes this one for a frame.
        m_take->setInterval(100);
        connect(m_take, &QTimer::timeout, this, [this] {
            if (!m_paused)
                takeNew();
        });
        m_take->start();
        catchUp();
    }
    refresh();
}

void TrafficLogView::setPaused(bool paused)
{
    if (m_paused == paused)
        return;
    m_paused = paused;
    {
        const QSignalBlocker block(m_pause);
        m_pause->setChecked(paused);
    }
    m_pause->setText(paused ? tr("&Resume") : tr("&Pause"));
    if (!paused)
        catchUp();
}

void TrafficLogView::clear()
{
    m_pending.clear();
    m_rowsInLog = false;
    m_shownUpTo = m_lastSequence;
    m_model->clear();
    m_statistics.clear();
    refresh();
}

bool TrafficLogView::saveTo(const QString& path, QString* error)
{
    if (!m_paused)
        takeNew();
    flush();
    QByteArray text;
    for (int row = 0; row < m_filter->rowCount(); ++row) {
        const int source = m_filter->mapToSource(m_filter->index(row, 0)).row();
        text += m_model->entry(source).toLine().toUtf8() + '\n';
    }
    return OutputFile::write(path, text, error);
}

void TrafficLogView::addEntry(const TrafficEntry& entry)
{
    if (m_paused || entry.sequence <= m_lastSequence)
        return; // paused: catchUp() takes it from the log; older: already shown
    m_lastSequence = entry.sequence;
    // Out of view the frames are not copied a second time: the log keeps as many as the
    // table shows, and flush() reads them from it when the view is seen again.
    if (m_log && outOfView())
        m_rowsInLog = true;
    else
        m_pending.append(entry); // rows are added in batches by refresh(): one re-layout
    m_statistics.add(entry);
    addDriveChoice(entry.slave);
    refreshSoon();
}

void TrafficLogView::takeNew()
{
    if (!m_log)
        return;
    const QVector<TrafficEntry> entries = m_log->entriesAfter(m_lastSequence);
    for (const TrafficEntry& entry : entries)
        addEntry(entry);
}

void TrafficLogView::catchUp()
{
    if (!m_log)
        return;
    takeNew();
    flush();
    m_table->scrollToBottom();
}

void TrafficLogView::addDriveChoice(int slave)
{
    // Asked for every frame (a thousand a second): a set, not a search through the list.
    if (m_driveChoices.contains(slave))
        return;
    m_driveChoices.insert(slave);
    int index = 1;
    while (index < m_drive->count() && m_drive->itemData(index).toInt() < slave)
        ++index;
    m_drive->insertItem(index, slave == 0 ? tr("Broadcast") : tr("Drive %1").arg(slave), slave);
}

void TrafficLogView::applyFilters()
{
    m_filter->setSlave(m_drive->currentData().toInt());
    m_filter->setDirection(TrafficLogFilter::DirectionFilter(m_direction->currentData().toInt()));
    m_filter->setErrorsOnly(m_errorsOnly->isChecked());
}

void TrafficLogView::refreshSoon()
{
    if (!m_refresh->isActive())
        m_refresh->start();
}

bool TrafficLogView::outOfView() const
{
    return window()->isVisible() && !isVisible();
}

void TrafficLogView::flush()
{
    if (m_rowsInLog) {
        // Those still in the log, up to the last one the statistics counted (later ones are
        // taken with the next batch).
        m_rowsInLog = false;
        m_pending = m_log->entriesAfter(m_shownUpTo);
        while (!m_pending.isEmpty() && m_pending.last().sequence > m_lastSequence)
            m_pending.removeLast();
    }
    if (!m_pending.isEmpty())
        m_shownUpTo = m_pending.last().sequence;
    m_model->append(m_pending);
    m_pending.clear();
}

void TrafficLogView::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    refresh();
}

void TrafficLogView::refresh()
{
    // Out of view the rows and statistics are laid out when the view is seen (showEvent),
    // not five times a second.
    if (outOfView())
        return;
    flush();
    if (!m_paused)
        m_table->scrollToBottom();
    // The addresses that never answered (a scan asks 247) in one line, not a row each; one or
    // two (a drive gone quiet) keep rows of their own.
    const QVector<int> silent = m_statistics.unanswered();
    const bool summarise = silent.size() > 2;
    QVector<int> slaves = m_statistics.slaves();
    if (summarise)
        slaves.removeIf([&silent](int s) { return silent.contains(s); });
    m_stats->clearSpans();
    m_stats->setRowCount(int(slaves.size()) + (summarise ? 1 : 0));
    // The summary first: the statistics pane is small, and this is what a scan leaves.
    const int first = summarise ? 1 : 0;
    if (summarise) {
        const int row = 0;
        const QString ranges = TrafficStatistics::rangesText(silent);
        // More than two: the plural is always right.
        auto* item = cell(tr("%1 addresses did not answer: %2").arg(silent.size()).arg(ranges));
        item->setTextAlignment(Qt::AlignLeft | Qt::AlignVCenter);
        item->setToolTip(tr("No reply from machine numbers %1").arg(ranges));
        m_stats->setItem(row, 0, item);
        for (int column = 1; column < m_stats->columnCount(); ++column)
            m_stats->setItem(row, column, cell(QString()));
        m_stats->setSpan(row, 0, 1, m_stats->columnCount());
    }
    for (int i = 0; i < slaves.size(); ++i) {
        const int row = first + int(i);
        const DriveTrafficStats s = m_statistics.drive(slaves[i]);
        const QStringList texts = {s.slave == 0 ? tr("Broadcast") : QString::number(s.slave),
                                   QString::number(s.requests),
                                   QString::number(s.replies),
                                   QString::number(s.timeouts),
                                   QString::number(s.crcErrors),
                                   QString::number(s.exceptions),
                                   QString::number(s.garbled),
                                   QString::number(s.late),
                                   QString::number(s.meanMs(), 'f', 1),
                                   QString::number(s.maxMs, 'f', 1)};
        for (int column = 0; column < texts.size(); ++column)
            setStatsCell(row, column, texts[column]);
    }
}

void TrafficLogView::setStatsCell(int row, int column, const QString& text)
{
    // Five times a second: the items stay, and only a count that changed is repainted.
    QTableWidgetItem* item = m_stats->item(row, column);
    if (item && m_stats->columnSpan(row, column) == 1 &&
        item->textAlignment() == int(Qt::AlignRight | Qt::AlignVCenter) &&
        item->toolTip().isEmpty()) {
        if (item->text() != text)
            item->setText(text);
        return;
    }
    m_stats->setItem(row, column, cell(text));
}

void TrafficLogView::save()
{
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save traffic log"), QStringLiteral("traffic.txt"), tr("Text files (*.txt)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!saveTo(path, &error))
        QMessageBox::warning(this, tr("Save traffic log"),
                             tr("Could not save %1: %2").arg(path, error));
}

} // namespace opentop
