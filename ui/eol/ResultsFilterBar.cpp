#include "ui/eol/ResultsFilterBar.h"

#include "model/eol/CertificateHtml.h"

#include <QComboBox>
#include <QDateTime>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace opentop {

ResultsFilterBar::ResultsFilterBar(QWidget* parent)
    : QWidget(parent)
{
    m_url = new QLineEdit(this);
    m_url->setPlaceholderText(tr("SQLite file or postgresql://user@host/database"));
    auto* open = new QPushButton(tr("Open"), this);
    auto* browse = new QPushButton(tr("File…"), this);
    auto* urlRow = new QHBoxLayout;
    urlRow->addWidget(m_url, 1);
    urlRow->addWidget(open);
    urlRow->addWidget(browse);

    m_serial = new QLineEdit(this);
    m_serial->setPlaceholderText(tr("any; * and ? as wildcards (SN-10*)"));
    m_recipe = new QLineEdit(this);
    m_recipe->setPlaceholderText(tr("any"));
    m_station = new QLineEdit(this);
    m_station->setPlaceholderText(tr("any"));
    m_period = new QComboBox(this);
    m_period->addItem(tr("Today"), 0);
    m_period->addItem(tr("Last 24 hours"), 1);
    m_period->addItem(tr("Last 7 days"), 7);
    m_period->addItem(tr("Last 30 days"), 30);
    m_period->addItem(tr("All"), -1);
    m_period->setCurrentIndex(2);
    m_verdict = new QComboBox(this);
    m_verdict->addItem(tr("Any"), QString());
    for (UnitStatus s : {UnitStatus::Pass, UnitStatus::Fail, UnitStatus::Error, UnitStatus::Aborted,
                         UnitStatus::Interrupted, UnitStatus::Running})
        m_verdict->addItem(CertificateHtml::verdictText(s), unitStatusName(s));
    auto* find = new QPushButton(tr("Search"), this);
    find->setDefault(true);

    auto* filters = new QHBoxLayout;
    for (auto [label, widget] : {std::pair<QString, QWidget*>{tr("Serial:"), m_serial},
                                 {tr("Recipe:"), m_recipe},
                                 {tr("Station:"), m_station},
                                 {tr("Period:"), m_period},
                                 {tr("Verdict:"), m_verdict}}) {
        filters->addWidget(new QLabel(label, this));
        filters->addWidget(widget, qobject_cast<QLineEdit*>(widget) ? 1 : 0);
    }
    filters->addWidget(find);

    auto* layout = new QFormLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addRow(tr("Database:"), urlRow);
    layout->addRow(filters);

    connect(open, &QPushButton::clicked, this, [this] { emit openAsked(m_url->text()); });
    connect(m_url, &QLineEdit::returnPressed, open, &QPushButton::click);
    connect(browse, &QPushButton::clicked, this, &ResultsFilterBar::chooseDatabase);
    connect(find, &QPushButton::clicked, this, &ResultsFilterBar::searchAsked);
    for (QLineEdit* e : {m_serial, m_recipe, m_station})
        connect(e, &QLineEdit::returnPressed, this, &ResultsFilterBar::searchAsked);
    connect(m_period, &QComboBox::activated, this, &ResultsFilterBar::searchAsked);
    connect(m_verdict, &QComboBox::activated, this, &ResultsFilterBar::searchAsked);
}

QString ResultsFilterBar::url() const
{
    return m_url->text();
}

void ResultsFilterBar::setUrl(const QString& url)
{
    m_url->setText(url);
}

ResultFilter ResultsFilterBar::filter() const
{
    ResultFilter filter;
    filter.serial = m_serial->text().trimmed();
    filter.recipe = m_recipe->text().trimmed();
    filter.station = m_station->text().trimmed();
    filter.status = unitStatusFromName(m_verdict->currentData().toString());
    const int days = m_period->currentData().toInt();
    const QDateTime now = QDateTime::currentDateTime();
    if (days == 0)
        filter.from = now.date().startOfDay().toUTC();
    else if (days > 0)
        filter.from = now.addDays(-days).toUTC();
    return filter;
}

void ResultsFilterBar::chooseDatabase()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open results database"), QFileInfo(m_url->text()).absolutePath(),
        tr("SQLite databases (*.db *.sqlite);;All files (*)"));
    if (path.isEmpty())
        return;
    m_url->setText(path);
    emit openAsked(path);
}

} // namespace opentop
