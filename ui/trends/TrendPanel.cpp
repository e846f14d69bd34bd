#include "ui/trends/TrendPanel.h"

#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "model/profile/RoleEvaluator.h"
#include "model/session/DeviceSession.h"
#include "ui/trends/TrendChart.h"
#include "ui/trends/TrendDefaults.h"

#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace opentop {

namespace {

constexpr int kSlaveRole = Qt::UserRole;
constexpr int kKeyRole = Qt::UserRole + 1;

// The quantities of a drive worth a trend: numeric monitor values, as TrendHistory keeps them.
QVector<const ParameterMeta*> trendParameters(const Profile& profile)
{
    QVector<const ParameterMeta*> list;
    const ProfileRole* role = profile.role(QStringLiteral("monitor"));
    for (const QString& name : role ? role->parameters : QStringList()) {
        const ParameterMeta* meta = profile.parameter(name);
        if (meta && meta->isNumeric() && meta->spec.options.isEmpty())
            list << meta;
    }
    return list;
}

} // namespace

TrendPanel::TrendPanel(MonitorHub* hub, QWidget* parent)
    : QWidget(parent)
    , m_hub(hub)
    , m_chart(new TrendChart(hub, this))
    , m_tree(new QTreeWidget(this))
    , m_rate(new QComboBox(this))
    , m_window(new QComboBox(this))
    , m_pause(new QPushButton(tr("Pause"), this))
    , m_live(new QPushButton(tr("Live"), this))
{
    m_rate->setObjectName(QStringLiteral("pollRate"));
    m_rate->setToolTip(tr("How often each charted drive is polled. Commands you give always go "
                          "first; the drives take turns on the bus."));
    for (int ms : pollIntervals())
        m_rate->addItem(pollRateText(ms), ms);
    syncRate(hub->interval());
    connect(m_rate, &QComboBox::currentIndexChanged, this,
            [this](int index) { m_hub->setInterval(m_rate->itemData(index).toInt()); });
    connect(hub, &MonitorHub::intervalChanged, this, &TrendPanel::syncRate);

    m_window->setObjectName(QStringLiteral("timeWindow"));
    const QVector<QPair<QString, int>> windows{
        {tr("30 s"), 30}, {tr("1 min"), 60}, {tr("5 min"), 300}, {tr("15 min"), 900}};
    for (const auto& [text, seconds] : windows)
        m_window->addItem(text, seconds);
    m_window->setCurrentIndex(m_window->findData(m_chart->windowSeconds()));
    connect(m_window, &QComboBox::currentIndexChanged, this,
            [this](int index) { m_chart->setWindowSeconds(m_window->itemData(index).toInt()); });

    m_pause->setObjectName(QStringLiteral("pause"));
    m_pause->setCheckable(true);
    m_pause->setToolTip(tr("Freezes the chart; the values keep being recorded."));
    connect(m_pause, &QPushButton::toggled, m_chart, &TrendChart::setPaused);
    connect(m_chart, &TrendChart::pausedChanged, this, [this](bool paused) {
        m_pause->setChecked(paused);
        m_pause->setText(paused ? tr("Resume") : tr("Pause"));
    });
    m_live->setObjectName(QStringLiteral("live"));
    m_live->setToolTip(tr("Back to the latest values after zooming or pausing."));
    m_live->setEnabled(false);
    connect(m_live, &QPushButton::clicked, m_chart, &TrendChart::resetZoom);
    connect(m_chart, &TrendChart::followingChanged, this,
            [this](bool following) { m_live->setEnabled(!following); });
    auto* clear = new QPushButton(tr("Clear markers"), this);
    clear->setObjectName(QStringLiteral("clearMarkers"));
    connect(clear, &QPushButton::clicked, m_chart, &TrendChart::clearMarkers);
    auto* csv = new QPushButton(tr("Export CSV…"), this);
    csv->setObjectName(QStringLiteral("exportCsv"));
    connect(csv, &QPushButton::clicked, this, &TrendPanel::exportCsvClicked);
    auto* png = new QPushButton(tr("Export PNG…"), this);
    png->setObjectName(QStringLiteral("exportPng"));
    connect(png, &QPushButton::clicked, this, &TrendPanel::exportPngClicked);

    m_tree->setObjectName(QStringLiteral("trendSources"));
    m_tree->setHeaderLabels({tr("Drive / quantity")});
    m_tree->header()->setStretchLastSection(true);
    connect(m_tree, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item) {
        if (m_updating || !item->parent())
            return;
        const Key key(item->data(0, kSlaveRole).toInt(), item->data(0, kKeyRole).toString());
        if (item->checkState(0) == Qt::Checked)
            m_checked.insert(key);
        else
            m_checked.remove(key);
        applyChecks();
    });

    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Poll rate:"), this));
    controls->addWidget(m_rate);
    controls->addWidget(new QLabel(tr("Window:"), this));
    controls->addWidget(m_window);
    for (QPushButton* b : {m_pause, m_live, clear, csv, png})
        controls->addWidget(b);
    controls->addStretch(1);
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(m_tree);
    splitter->addWidget(m_chart);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({200, 800});
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(splitter, 1);

    BusDrives* drives = hub->drives();
    connect(drives, &BusDrives::driveAdded, this, &TrendPanel::rebuildTree);
    connect(drives, &BusDrives::driveChanged, this, &TrendPanel::rebuildTree);
    connect(drives, &BusDrives::driveRemoved, this, &TrendPanel::rebuildTree);
    rebuildTree();
}

QVector<int> TrendPanel::pollIntervals()
{
    return {1000, 500, 200, 100, 50};
}

QString TrendPanel::pollRateText(int ms)
{
    return tr("%1 Hz (%2 ms)").arg(QString::number(1000.0 / ms, 'g', 3)).arg(ms);
}

void TrendPanel::syncRate(int ms)
{
    int index = m_rate->findData(ms);
    if (index < 0) {
        // Another view chose a rate not in the list: show it as it is.
        m_rate->addItem(pollRateText(ms), ms);
        index = m_rate->count() - 1;
    }
    const QSignalBlocker block(m_rate);
    m_rate->setCurrentIndex(index);
}

QSet<TrendPanel::Key> TrendPanel::defaultsFor(int slave) const
{
    QSet<Key> keys;
    const DeviceSession* session = m_hub->drives()->session(slave);
    if (!session)
        return keys;
    if (!m_preselected) {
        if (const ParameterMeta* meta =
                RoleEvaluator::parameter(session->profile(), QStringLiteral("currentSpeed")))
            keys.insert(Key(slave, meta->name));
    } else if (m_selected.contains(slave)) {
        for (const TrendSource& s : TrendDefaults::forDrive(session->profile(), slave))
            keys.insert(Key(slave, s.key));
    }
    return keys;
}

void TrendPanel::showDrives(const QVector<int>& slaves)
{
    m_preselected = true;
    m_selected = slaves;
    m_checked.clear();
    m_known.clear(); // every drive gets the new defaults
    rebuildTree();
}

void TrendPanel::rebuildTree()
{
    m_updating = true;
    m_tree->clear();
    const BusDrives* drives = m_hub->drives();
    QSet<int> present;
    for (int slave : drives->slaves()) {
        const DeviceSession* session = drives->session(slave);
        if (!session)
            continue; // not identified: nothing to poll
        present.insert(slave);
        if (!m_known.contains(slave))
            m_checked.unite(defaultsFor(slave));
        auto* drive = new QTreeWidgetItem(m_tree, {TrendChart::driveTitle(drives, slave)});
        drive->setFlags(drive->flags() | Qt::ItemIsUserCheckable | Qt::ItemIsAutoTristate);
        for (const ParameterMeta* meta : trendParameters(session->profile())) {
            const QString text = meta->spec.unit.isEmpty()
                                     ? meta->label
                                     : tr("%1 [%2]").arg(meta->label, meta->spec.unit);
            auto* item = new QTreeWidgetItem(drive, {text});
            item->setData(0, kSlaveRole, slave);
            item->setData(0, kKeyRole, meta->name);
            item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
            item->setCheckState(0, m_checked.contains(Key(slave, meta->name)) ? Qt::Checked
                                                                              : Qt::Unchecked);
        }
        drive->setExpanded(true);
    }
    // Forget the checks of drives that are gone.
    for (auto it = m_checked.begin(); it != m_checked.end();)
        it = present.contains(it->first) ? std::next(it) : m_checked.erase(it);
    m_known = present;
    m_updating = false;
    applyChecks();
}

bool TrendPanel::setChecked(int slave, const QString& key, bool checked)
{
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* drive = m_tree->topLevelItem(i);
        for (int j = 0; j < drive->childCount(); ++j) {
            QTreeWidgetItem* item = drive->child(j);
            if (item->data(0, kSlaveRole).toInt() == slave &&
                item->data(0, kKeyRole).toString() == key) {
                item->setCheckState(0, checked ? Qt::Checked : Qt::Unchecked);
                return true;
            }
        }
    }
    return false;
}

void TrendPanel::applyChecks()
{
    // In tree order: drive by drive, quantities as the profile lists them.
    QVector<TrendSource> sources;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* drive = m_tree->topLevelItem(i);
        for (int j = 0; j < drive->childCount(); ++j) {
            const QTreeWidgetItem* item = drive->child(j);
            if (item->checkState(0) == Qt::Checked)
                sources << TrendSource{item->data(0, kSlaveRole).toInt(),
                                       item->data(0, kKeyRole).toString()};
        }
    }
    m_chart->setSources(sources);
}

void TrendPanel::exportCsvClicked()
{
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export trend as CSV"), QStringLiteral("trend.csv"), tr("CSV files (*.csv)"));
    QString error;
    if (!path.isEmpty() && !m_chart->exportCsv(path, &error))
        QMessageBox::warning(this, tr("Export CSV"), error);
}

void TrendPanel::exportPngClicked()
{
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export trend as picture"),
                                     QStringLiteral("trend.png"), tr("PNG pictures (*.png)"));
    QString error;
    if (!path.isEmpty() && !m_chart->exportPng(path, &error))
        QMessageBox::warning(this, tr("Export PNG"), error);
}

} // namespace opentop
