#include "ui/eol/RecipeLimitsTable.h"

#include "model/profile/Profile.h"
#include "ui/eol/RecipeNumberText.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace opentop {

namespace {
const QString kParameter = QStringLiteral("parameter");
const QString kStatistic = QStringLiteral("statistic");
const QString kLower = QStringLiteral("lower");
const QString kUpper = QStringLiteral("upper");
const QString kUnit = QStringLiteral("unit");
} // namespace

RecipeLimitsTable::RecipeLimitsTable(const Profile* profile, const QJsonArray& limits,
                                     QWidget* parent)
    : QWidget(parent)
    , m_profile(profile)
    , m_table(new QTableWidget(0, 5, this))
{
    m_table->setObjectName(QStringLiteral("stepLimits"));
    m_table->setHorizontalHeaderLabels(
        {tr("Parameter"), tr("Statistic"), tr("Lower"), tr("Upper"), tr("Unit")});
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    // The parameter takes what is left; a limit's digits and the unit are short.
    QHeaderView* header = m_table->horizontalHeader();
    header->setSectionResizeMode(Parameter, QHeaderView::Stretch);
    header->setSectionResizeMode(Statistic, QHeaderView::ResizeToContents);
    header->setSectionResizeMode(Unit, QHeaderView::ResizeToContents);
    const int digits = m_table->fontMetrics().horizontalAdvance(QStringLiteral("-00000.00")) + 12;
    m_table->setColumnWidth(Lower, digits);
    m_table->setColumnWidth(Upper, digits);
    m_filling = true;
    m_table->setRowCount(int(limits.size()));
    for (int row = 0; row < limits.size(); ++row)
        fillRow(row, limits.at(row).toObject());
    m_filling = false;
    connect(m_table, &QTableWidget::itemChanged, this, [this] {
        if (!m_filling)
            emit changed();
    });

    auto* add = new QPushButton(tr("Add limit"), this);
    auto* remove = new QPushButton(tr("Remove limit"), this);
    connect(add, &QPushButton::clicked, this, &RecipeLimitsTable::addLimit);
    connect(remove, &QPushButton::clicked, this, &RecipeLimitsTable::removeSelected);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(tr("Limits (measured over the hold):"), this));
    layout->addWidget(m_table, 1);
    layout->addLayout(buttons);
}

void RecipeLimitsTable::fillRow(int row, const QJsonObject& limit)
{
    auto* parameter = new QComboBox(m_table);
    const QString name = limit.value(kParameter).toString();
    if (m_profile)
        for (const ParameterMeta& p : m_profile->parameters)
            if (p.isReadable() && p.isNumeric() && p.kind == QLatin1String("status"))
                parameter->addItem(p.label, p.name);
    if (!name.isEmpty() && parameter->findData(name) < 0)
        parameter->addItem(tr("(unknown: %1)").arg(name), name);
    parameter->setCurrentIndex(name.isEmpty() ? -1 : parameter->findData(name));
    m_table->setCellWidget(row, Parameter, parameter);
    auto* statistic = new QComboBox(m_table);
    for (const QString& s : {QStringLiteral("min"), QStringLiteral("mean"), QStringLiteral("max")})
        statistic->addItem(s, s);
    statistic->setCurrentIndex(
        std::max(0, statistic->findData(limit.value(kStatistic).toString())));
    m_table->setCellWidget(row, Statistic, statistic);
    m_table->setItem(row, Lower, new QTableWidgetItem(RecipeNumberText::text(limit.value(kLower))));
    m_table->setItem(row, Upper, new QTableWidgetItem(RecipeNumberText::text(limit.value(kUpper))));
    auto* unit = new QTableWidgetItem(limit.value(kUnit).toString());
    unit->setFlags(unit->flags() & ~Qt::ItemIsEditable);
    m_table->setItem(row, Unit, unit);
    connect(parameter, &QComboBox::currentIndexChanged, this, [this, row, parameter] {
        // The unit is the parameter's own: the checker refuses any other.
        m_table->item(row, Unit)->setText(unitOf(parameter->currentData().toString()));
        emit changed();
    });
    connect(statistic, &QComboBox::currentIndexChanged, this, &RecipeLimitsTable::changed);
}

void RecipeLimitsTable::addLimit()
{
    const int row = m_table->rowCount();
    m_filling = true;
    m_table->insertRow(row);
    fillRow(row, QJsonObject{{kStatistic, QStringLiteral("max")}});
    m_filling = false;
    m_table->selectRow(row);
    emit changed();
}

void RecipeLimitsTable::removeSelected()
{
    const QList<QTableWidgetItem*> items = m_table->selectedItems();
    const int row = items.isEmpty() ? m_table->currentRow() : items.first()->row();
    if (row < 0)
        return;
    // The rows' combo boxes know their row: fill the table again rather than shift them.
    QJsonArray rest = limits();
    rest.removeAt(row);
    m_filling = true;
    m_table->setRowCount(0);
    m_table->setRowCount(int(rest.size()));
    for (int r = 0; r < rest.size(); ++r)
        fillRow(r, rest.at(r).toObject());
    m_filling = false;
    emit changed();
}

QString RecipeLimitsTable::unitOf(const QString& parameter) const
{
    const ParameterMeta* meta = m_profile ? m_profile->parameter(parameter) : nullptr;
    return meta ? meta->spec.canonicalUnit : QString(); // as recipe files give units
}

QJsonArray RecipeLimitsTable::limits() const
{
    QJsonArray limits;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        auto* parameter = qobject_cast<QComboBox*>(m_table->cellWidget(row, Parameter));
        auto* statistic = qobject_cast<QComboBox*>(m_table->cellWidget(row, Statistic));
        QJsonObject limit{
            {kParameter, parameter ? parameter->currentData().toString() : QString()},
            {kStatistic, statistic ? statistic->currentData().toString() : QString()}};
        const QJsonValue lower = RecipeNumberText::value(m_table->item(row, Lower)->text());
        const QJsonValue upper = RecipeNumberText::value(m_table->item(row, Upper)->text());
        if (!lower.isUndefined())
            limit.insert(kLower, lower);
        if (!upper.isUndefined())
            limit.insert(kUpper, upper);
        limit.insert(kUnit, m_table->item(row, Unit)->text());
        limits << limit;
    }
    return limits;
}

} // namespace opentop
