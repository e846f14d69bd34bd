#include "ui/bus/BusPanel.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusScanner.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/bus/FixedLineHint.h"
#include "model/bus/LineFormatHint.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceIdentifier.h"
#include "transport/ModbusClient.h"
#include "ui/bus/BusListMenu.h"
#include "ui/bus/BusListModel.h"
#include "ui/bus/DriveLineDialog.h"

#include <QAction>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>

namespace opentop {

BusPanel::BusPanel(BusDrives* drives, DriveStatusPoller* poller, QWidget* parent)
    : QWidget(parent)
    , m_drives(drives)
    , m_poller(poller)
    , m_model(new BusListModel(this))
    , m_identifier(new DeviceIdentifier(drives->client(), ProfileRegistry::builtIn(), this))
    , m_scan(new QPushButton(tr("&Scan"), this))
    , m_from(new QSpinBox(this))
    , m_to(new QSpinBox(this))
    , m_add(new QPushButton(tr("A&dd drive…"), this))
    , m_progress(new QProgressBar(this))
    , m_cancel(new QPushButton(tr("Ca&ncel"), this))
    , m_message(new QLabel(this))
    , m_view(new QTableView(this))
    , m_menu(new BusListMenu(this, drives))
{
    m_model->setPoller(poller);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);

    auto* row = new QHBoxLayout;
    m_scan->setToolTip(tr("Ask every machine number of the range who answers"));
    row->addWidget(m_scan);
    auto* fromLabel = new QLabel(tr("&from"), this);
    fromLabel->setBuddy(m_from);
    auto* toLabel = new QLabel(tr("&to"), this);
    toLabel->setBuddy(m_to);
    for (QSpinBox* s : {m_from, m_to}) {
        s->setRange(1, 247);
        s->setAccelerated(true);
        s->setToolTip(tr("Machine numbers 1–247, as set on each drive's switches:\n%1")
                          .arg(DeviceInfo::switchHelp()));
    }
    m_from->setValue(1);
    m_to->setValue(247);
    connect(m_from, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        if (m_to->value() < v)
            m_to->setValue(v);
    });
    connect(m_to, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        if (m_from->value() > v)
            m_from->setValue(v);
    });
    row->addWidget(fromLabel);
    row->addWidget(m_from);
    row->addWidget(toLabel);
    row->addWidget(m_to);
    row->addStretch(1);
    m_add->setToolTip(tr("Identify one machine number and add it to the list"));
    row->addWidget(m_add);
    layout->addLayout(row);

    auto* progressRow = new QHBoxLayout;
    m_progress->setFormat(tr("%v of %m"));
    m_progress->setAccessibleName(tr("Scan progress"));
    progressRow->addWidget(m_progress, 1);
    m_cancel->setToolTip(tr("Stop the scan after the request on the wire"));
    progressRow->addWidget(m_cancel);
    layout->addLayout(progressRow);
    m_progress->setVisible(false);
    m_cancel->setVisible(false);
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // drives' names and models, errors
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_message);
    const FixedLineHint fixed = FixedLineHint::dcPotentiometer();
    m_fixedLine = new QPushButton(tr("Rescan at %1").arg(fixed.shortText()), this);
    m_fixedLine->setObjectName(QStringLiteral("fixedLineRescan"));
    m_fixedLine->setToolTip(fixed.explanation());
    m_fixedLine->setVisible(false);
    connect(m_fixedLine, &QPushButton::clicked, this, [this] {
        m_fixedLine->setVisible(false);
        emit fixedLineRescanRequested();
    });
    layout->addWidget(m_fixedLine, 0, Qt::AlignLeft);

    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setAlternatingRowColors(true);
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    m_view->setTabKeyNavigation(false); // Tab leaves the list; arrows move inside it
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setStretchLastSection(true);
    // What one looks at first (which drive, what it is doing, who controls it) comes first;
    // the window divides itself so that every column shows whole (WindowGeometry::divide).
    QHeaderView* header = m_view->horizontalHeader();
    int to = BusListModel::MachineNumber + 1;
    for (int column :
         {BusListModel::Name, BusListModel::Model, BusListModel::State, BusListModel::Priority})
        header->moveSection(header->visualIndex(column), to++);
    // A long name is shortened (the tooltip has it whole), not the state beside it; no names,
    // no room taken.
    header->setSectionResizeMode(BusListModel::Name, QHeaderView::Interactive);
    fitNameColumn();
    for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
        connect(m_model, signal, this, &BusPanel::fitNameColumn);
    connect(m_model, &QAbstractItemModel::modelReset, this, &BusPanel::fitNameColumn);
    connect(m_model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex& first, const QModelIndex& last) {
                if (first.column() <= BusListModel::Name && last.column() >= BusListModel::Name)
                    fitNameColumn();
            });
    m_view->setTextElideMode(Qt::ElideRight);
    m_view->setWordWrap(false); // one line a drive, shortened where narrow
    m_view->setAccessibleName(tr("Drives on the bus"));
    layout->addWidget(m_view, 1);

    setTabOrder(m_scan, m_from);
    setTabOrder(m_from, m_to);
    setTabOrder(m_to, m_add);
    setTabOrder(m_add, m_cancel);
    setTabOrder(m_cancel, m_view);

    connect(m_scan, &QPushButton::clicked, this, &BusPanel::scanClicked);
    connect(m_add, &QPushButton::clicked, this, &BusPanel::addClicked);
    connect(m_cancel, &QPushButton::clicked, this, &BusPanel::cancelScan);
    connect(m_view, &QWidget::customContextMenuRequested, this, &BusPanel::showContextMenu);
    connect(m_menu, &BusListMenu::message, this,
            [this](const QString& text) { showMessage(text); });
    // F2 names the machine of the current row, as it renames elsewhere.
    auto* name = new QAction(tr("Name this machine…"), m_view);
    name->setShortcut(QKeySequence(Qt::Key_F2));
    name->setShortcutContext(Qt::WidgetShortcut);
    m_view->addAction(name);
    connect(name, &QAction::triggered, this, [this] {
        if (m_view->currentIndex().isValid())
            m_menu->askName(m_model->slaveAt(m_view->currentIndex().row()));
    });
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            [this] { emit selectionChanged(selectedSlaves()); });

    connect(drives, &BusDrives::driveAdded, this, &BusPanel::syncDrive);
    connect(drives, &BusDrives::driveChanged, this, &BusPanel::syncDrive);
    connect(drives, &BusDrives::driveRemoved, m_model, &BusListModel::remove);
    for (int slave : drives->slaves())
        syncDrive(slave);
    updateButtons();
}

BusPanel::~BusPanel()
{
    if (m_scanner)
        m_scanner->disconnect(this);
}

void BusPanel::syncDrive(int slave)
{
    m_model->upsert(m_drives->info(slave));
    // The first drive that answers is selected, so its pages open without a click.
    if (m_view->selectionModel()->selectedRows().isEmpty() &&
        m_drives->info(slave).state == DeviceInfo::State::Present) {
        m_view->selectRow(m_model->rowOf(slave));
        m_view->setCurrentIndex(m_model->index(m_model->rowOf(slave), 0));
    }
}

void BusPanel::scanClicked()
{
    startScan(m_from->value(), m_to->value());
}

void BusPanel::startScan(int from, int to)
{
    if (isScanning())
        return;
    m_from->setValue(from);
    m_to->setValue(to);
    m_fixedLine->setVisible(false);
    delete m_scanner;
    m_scanner = new BusScanner(m_drives->client(), ProfileRegistry::builtIn(), this);
    m_scanner->setRange(from, to);
    connect(m_scanner, &BusScanner::found, this,
            [this](const DeviceInfo& info) { m_drives->update(info); });
    connect(m_scanner, &BusScanner::progress, this, [this](int done, int total, int slave) {
        m_progress->setMaximum(total);
        m_progress->setValue(done);
        m_progress->setFormat(tr("%v of %m (machine number %1)").arg(slave));
    });
    connect(m_scanner, &BusScanner::identificationRetry, this,
            [this](int slave, int attempt, int attempts) {
                showMessage(tr("Machine number %1 answered, identification failed: retrying "
                               "(%2 of %3)… Polling waits until the scan is over.")
                                .arg(slave)
                                .arg(attempt)
                                .arg(attempts),
                            true);
            });
    connect(m_scanner, &BusScanner::finished, this, &BusPanel::onScanFinished);
    m_progress->setRange(0, to - from + 1);
    m_progress->setValue(0);
    m_progress->setFormat(tr("%v of %m"));
    // The scanner holds the bus: polling waits, and the values shown age meanwhile.
    showMessage(tr("Scanning machine numbers %1–%2 on %3, %4 ms each… Polling waits until the "
                   "scan is over.")
                    .arg(from)
                    .arg(to)
                    .arg(m_drives->client()->describe())
                    .arg(m_scanner->waitMs()));
    m_scanner->start();
    updateButtons();
}

bool BusPanel::isScanning() const
{
    return m_scanner && m_scanner->isRunning();
}

void BusPanel::cancelScan()
{
    if (!isScanning())
        return;
    m_cancel->setEnabled(false);
    showMessage(tr("Cancelling after the request on the wire…"));
    m_scanner->cancel();
}

void BusPanel::onScanFinished()
{
    const int from = m_scanner->from();
    const int scanned = m_scanner->scannedCount();
    const QVector<int> unidentified = BusScanner::unidentified(m_scanner->devices());
    const int found = int(m_scanner->devices().size() - unidentified.size());
    // Drives listed earlier that no longer answer in the range asked are shown as such.
    QVector<int> answered;
    for (const DeviceInfo& d : m_scanner->devices())
        answered << d.slave;
    for (int slave : m_drives->slaves()) {
        if (slave >= from && slave < from + scanned && !answered.contains(slave)) {
            DeviceInfo gone = m_drives->info(slave);
            gone.state = DeviceInfo::State::Absent;
            gone.detail = tr("Did not answer the last scan.");
            m_drives->update(gone);
        }
    }
    const double seconds = m_scanner->elapsedMs() / 1000.0;
    if (!m_scanner->error().isEmpty()) {
        showMessage(tr("The scan stopped at machine number %1: %2")
                        .arg(from + scanned)
                        .arg(m_scanner->error()),
                    true);
    } else if (m_scanner->wasCancelled()) {
        showMessage(tr("Scan cancelled after machine numbers %1–%2 (%3 of %4): %n drive(s) "
                       "found.",
                       nullptr, found)
                        .arg(from)
                        .arg(from + scanned - 1)
                        .arg(scanned)
                        .arg(m_scanner->total()));
    } else {
        QString text = tr("%n drive(s) found on machine numbers %1–%2 in %3 s.", nullptr, found)
                           .arg(from)
                           .arg(m_scanner->to())
                           .arg(seconds, 0, 'f', 1);
        // Nobody answered: a DC controller in potentiometer/analog control talks only at its
        // fixed settings, whatever it was configured to.
        const FixedLineHint fixed = FixedLineHint::dcPotentiometer();
        const bool offer = found == 0 && fixed.worthRetrying(m_drives->client()->settings(), from,
                                                             m_scanner->to());
        const QString missed = LineFormatHint::missedText(
            ProfileRegistry::builtIn(), m_drives->client()->settings(), m_scanner->devices());
        if (offer)
            text += QLatin1Char(' ') + fixed.explanation();
        else if (!missed.isEmpty()) // a drive of its own format is added with it
            text += QLatin1Char(' ') + missed + QLatin1Char(' ') +
                    tr("If one is on this bus, add it with Add drive and its line format.");
        // Something answered there but never said what it is: not a drive of the list, and
        // not nothing either.
        for (int slave : unidentified)
            text += QLatin1Char(' ') +
                    tr("Machine number %1 answered, but its identification failed, also when "
                       "asked again: add it by hand with Add drive…, or check its line settings "
                       "and scan again.")
                        .arg(slave);
        showMessage(text, found == 0 || !unidentified.isEmpty());
        m_fixedLine->setVisible(offer);
    }
    updateButtons();
    emit scanFinished();
}

void BusPanel::addClicked()
{
    DriveLineDialog::askToAdd(this, m_drives, m_from->value(),
                              [this](int slave) { addDrive(slave); });
}

void BusPanel::addDrive(int slave)
{
    ++m_adding;
    updateButtons();
    showMessage(tr("Asking machine number %1…").arg(slave));
    m_identifier->identify(slave, [this, slave](const DeviceInfo& info) {
        --m_adding;
        m_drives->update(info);
        if (info.state == DeviceInfo::State::Present)
            showMessage(tr("Machine number %1: %2 added.").arg(slave).arg(info.model));
        else
            showMessage(tr("Machine number %1: %2 %3")
                            .arg(slave)
                            .arg(DeviceInfo::stateText(info.state), info.detail),
                        info.state != DeviceInfo::State::Unidentified);
        if (m_poller)
            m_poller->pollNow();
        updateButtons();
        emit driveAddedByNumber(slave);
    });
}

QVector<int> BusPanel::selectedSlaves() const
{
    QVector<int> slaves;
    for (const QModelIndex& i : m_view->selectionModel()->selectedRows())
        slaves << m_model->slaveAt(i.row());
    std::sort(slaves.begin(), slaves.end());
    return slaves;
}

QString BusPanel::message() const
{
    return m_message->text();
}

void BusPanel::showMessage(const QString& text, bool problem)
{
    m_message->setText(text);
    m_message->setStyleSheet(problem ? QStringLiteral("color: #b01c1c;") : QString());
}

void BusPanel::fitNameColumn()
{
    QHeaderView* header = m_view->horizontalHeader();
    const int widest = m_view->fontMetrics().horizontalAdvance(QStringLiteral("Infeed 3")) + 20;
    int wanted = header->sectionSizeHint(BusListModel::Name);
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const QString name = m_model->index(row, BusListModel::Name).data().toString();
        wanted = std::max(wanted, m_view->fontMetrics().horizontalAdvance(name) + 20);
    }
    header->resizeSection(BusListModel::Name, std::min(wanted, widest));
}

void BusPanel::updateButtons()
{
    const bool scanning = isScanning();
    m_scan->setEnabled(!scanning && m_adding == 0);
    m_add->setEnabled(!scanning);
    m_from->setEnabled(!scanning);
    m_to->setEnabled(!scanning);
    m_progress->setVisible(scanning || (m_scanner && m_progress->value() > 0));
    m_cancel->setVisible(scanning);
    m_cancel->setEnabled(scanning);
}

QMenu* BusPanel::contextMenuFor(const QVector<int>& slaves, QWidget* parent)
{
    return m_menu->menuFor(slaves, parent);
}

void BusPanel::showContextMenu(const QPoint& pos)
{
    // The keyboard's menu key asks about the current row, not the row under the mouse.
    QModelIndex index = m_view->indexAt(pos);
    if (!index.isValid())
        index = m_view->currentIndex();
    if (!index.isValid())
        return;
    QVector<int> slaves = selectedSlaves();
    const int clicked = m_model->slaveAt(index.row());
    if (!slaves.contains(clicked))
        slaves = {clicked};
    QMenu* menu = contextMenuFor(slaves, this);
    menu->setAttribute(Qt::WA_DeleteOnClose);
    menu->popup(m_view->viewport()->mapToGlobal(
        m_view->indexAt(pos).isValid() ? pos : m_view->visualRect(index).center()));
}

} // namespace opentop
