#include "ui/eol/RecipePositionForm.h"

#include "ui/eol/RecipeStepsEditor.h"

#include "model/files/BackupReader.h"
#include "model/profile/Profile.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "model/profile/ValueContext.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QJsonArray>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace opentop {

namespace {

const QString kName = QStringLiteral("name");

QStringList listOf(const QJsonValue& value)
{
    QStringList out;
    for (const QJsonValue& v : value.toArray())
        out << v.toString();
    return out;
}

QJsonArray arrayOf(const QString& text)
{
    QJsonArray out;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
        if (!part.trimmed().isEmpty())
            out << part.trimmed();
    return out;
}

// A cell's text as the file holds it: a number where it reads as one, else the text (an
// enumeration's label).
QJsonValue valueOf(const QString& text)
{
    bool ok = false;
    const double number = text.trimmed().toDouble(&ok);
    return ok ? QJsonValue(number) : QJsonValue(text.trimmed());
}

QString textOf(const QJsonValue& value)
{
    return value.isDouble() ? QString::number(value.toDouble(), 'g', 10) : value.toString();
}

// A new setting starts at the factory default (else the lowest allowed value), as the file
// writes it: an enumeration's label, else the engineering number.
QJsonValue startValue(const ParameterMeta& meta)
{
    double raw = meta.spec.defaultRaw.value_or(0);
    if (!meta.spec.defaultRaw && !meta.spec.ranges.isEmpty())
        raw = meta.spec.ranges.first().min;
    else if (!meta.spec.defaultRaw && !meta.spec.options.isEmpty())
        raw = double(meta.spec.options.first().value);
    const ParamValue v = ValueCodec::decode(meta, ValueCodec::rawToRegisters(meta, raw));
    return meta.spec.options.isEmpty() ? QJsonValue(v.number) : QJsonValue(v.text);
}

// A new per-unit value's range: the widest allowed interval (never across a gap, such as the
// DBU's 0 or 250–3000 r/min) for the position's first allowed variant.
QPair<double, double> rangeOf(const ParameterMeta& meta, const QString& variant)
{
    ValueContext context;
    context.variant = variant;
    const ValueSpec& spec = meta.specFor(context);
    QPair<double, double> widest{0, 0};
    for (const ValueRange& r : spec.ranges)
        if (r.max - r.min >= widest.second - widest.first)
            widest = {r.min, r.max};
    return {widest.first * spec.scale, widest.second * spec.scale};
}

int rowOf(const QTableWidget* table, const QString& name)
{
    for (int row = 0; row < table->rowCount(); ++row)
        if (table->item(row, 1)->text() == name)
            return row;
    return -1;
}

QTableWidgetItem* fixed(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

QTableWidget* makeTable(const QStringList& headers, QWidget* parent)
{
    auto* table = new QTableWidget(0, int(headers.size()), parent);
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->hide();
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->horizontalHeader()->setStretchLastSection(true);
    return table;
}

} // namespace

RecipePositionForm::RecipePositionForm(QWidget* parent)
    : QWidget(parent)
{
    m_machineNumber = new QSpinBox(this);
    m_machineNumber->setRange(1, 247);
    m_name = new QLineEdit(this);
    m_family = new QLabel(this);
    m_family->setTextFormat(Qt::PlainText); // as the recipe file names it
    m_variants = new QLineEdit(this);
    m_variants->setPlaceholderText(tr("every variant of the family, e.g. dbu200, dbu400"));
    m_firmware = new QLineEdit(this);
    m_firmware->setPlaceholderText(tr("any firmware, e.g. 1.5, 1.6"));

    m_settings = makeTable({tr("Setting"), tr("Name"), tr("Value"), tr("Unit")}, this);
    m_unitValues = makeTable(
        {tr("Setting"), tr("Name"), tr("Min"), tr("Max"), tr("Unit"), tr("Source")}, this);
    m_steps = new RecipeStepsEditor(this);

    auto withButtons = [this](QTableWidget* table, bool unitValue) {
        auto* page = new QWidget(this);
        auto* add =
            new QPushButton(unitValue ? tr("Add per-unit value…") : tr("Add setting…"), page);
        auto* remove = new QPushButton(tr("Remove"), page);
        connect(add, &QPushButton::clicked, this, [this, unitValue] { chooseSetting(unitValue); });
        connect(remove, &QPushButton::clicked, this, [this, table] { removeRow(table); });
        auto* buttons = new QHBoxLayout;
        buttons->addWidget(add);
        buttons->addWidget(remove);
        buttons->addStretch(1);
        auto* layout = new QVBoxLayout(page);
        layout->addWidget(table, 1);
        layout->addLayout(buttons);
        return page;
    };
    auto* tabs = m_tabs = new QTabWidget(this);
    tabs->addTab(withButtons(m_settings, false), tr("Settings"));
    tabs->addTab(withButtons(m_unitValues, true), tr("Per-unit values"));
    tabs->addTab(m_steps, tr("Test steps"));

    auto* form = new QFormLayout;
    form->addRow(tr("Machine number:"), m_machineNumber);
    form->addRow(tr("Name:"), m_name);
    form->addRow(tr("Family:"), m_family);
    form->addRow(tr("Allowed variants:"), m_variants);
    form->addRow(tr("Allowed firmware:"), m_firmware);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(form);
    layout->addWidget(tabs, 1);

    auto emitChanged = [this] {
        if (!m_filling)
            emit changed();
    };
    connect(m_machineNumber, &QSpinBox::valueChanged, this, emitChanged);
    for (QLineEdit* e : {m_name, m_variants, m_firmware})
        connect(e, &QLineEdit::textEdited, this, emitChanged);
    connect(m_settings, &QTableWidget::itemChanged, this, emitChanged);
    connect(m_unitValues, &QTableWidget::itemChanged, this, emitChanged);
    connect(m_steps, &RecipeStepsEditor::changed, this, emitChanged);
}

void RecipePositionForm::setPosition(const QJsonObject& position)
{
    m_filling = true;
    m_position = position;
    const QString family = position.value(QStringLiteral("family")).toString();
    m_profile = ProfileRegistry::builtIn().family(family);
    m_machineNumber->setValue(position.value(QStringLiteral("machineNumber")).toInt());
    m_name->setText(position.value(kName).toString());
    m_family->setText(m_profile ? tr("%1 (%2)").arg(m_profile->name, family) : family);
    m_variants->setText(
        listOf(position.value(QStringLiteral("variants"))).join(QStringLiteral(", ")));
    m_firmware->setText(
        listOf(position.value(QStringLiteral("firmware"))).join(QStringLiteral(", ")));
    fillSettings(position.value(QStringLiteral("settings")).toArray());
    fillUnitValues(position.value(QStringLiteral("unitValues")).toArray());
    m_steps->setProfile(m_profile);
    m_steps->setSteps(position.value(QStringLiteral("steps")).toArray());
    m_filling = false;
}

void RecipePositionForm::fillSettings(const QJsonArray& settings)
{
    m_settings->setRowCount(0);
    for (const QJsonValue& v : settings) {
        const QJsonObject s = v.toObject();
        const int row = m_settings->rowCount();
        m_settings->insertRow(row);
        const QString name = s.value(kName).toString();
        m_settings->setItem(row, 0, fixed(labelOf(name)));
        m_settings->setItem(row, 1, fixed(name));
        m_settings->setItem(row, 2, new QTableWidgetItem(textOf(s.value(QStringLiteral("value")))));
        m_settings->setItem(row, 3, fixed(s.value(QStringLiteral("unit")).toString()));
    }
    m_settings->resizeColumnsToContents();
}

void RecipePositionForm::fillUnitValues(const QJsonArray& values)
{
    m_unitValues->setRowCount(0);
    for (const QJsonValue& v : values) {
        const QJsonObject u = v.toObject();
        const int row = m_unitValues->rowCount();
        m_unitValues->insertRow(row);
        const QString name = u.value(kName).toString();
        m_unitValues->setItem(row, 0, fixed(labelOf(name)));
        m_unitValues->setItem(row, 1, fixed(name));
        m_unitValues->setItem(row, 2, new QTableWidgetItem(textOf(u.value(QStringLiteral("min")))));
        m_unitValues->setItem(row, 3, new QTableWidgetItem(textOf(u.value(QStringLiteral("max")))));
        m_unitValues->setItem(row, 4, fixed(u.value(QStringLiteral("unit")).toString()));
        auto* source = new QComboBox(m_unitValues);
        source->addItem(tr("CSV file"), QStringLiteral("csv"));
        source->addItem(tr("typed by the operator"), QStringLiteral("operator"));
        source->setCurrentIndex(
            qMax(0, source->findData(u.value(QStringLiteral("source")).toString())));
        connect(source, &QComboBox::currentIndexChanged, this, [this] {
            if (!m_filling)
                emit changed();
        });
        m_unitValues->setCellWidget(row, 5, source);
    }
    m_unitValues->resizeColumnsToContents();
}

QJsonObject RecipePositionForm::position() const
{
    QJsonObject p = m_position;
    p.insert(QStringLiteral("machineNumber"), m_machineNumber->value());
    if (m_name->text().trimmed().isEmpty())
        p.remove(kName);
    else
        p.insert(kName, m_name->text().trimmed());
    p.insert(QStringLiteral("variants"), arrayOf(m_variants->text()));
    p.insert(QStringLiteral("firmware"), arrayOf(m_firmware->text()));
    QJsonArray settings;
    for (int row = 0; row < m_settings->rowCount(); ++row) {
        QJsonObject s{{kName, m_settings->item(row, 1)->text()},
                      {QStringLiteral("value"), valueOf(m_settings->item(row, 2)->text())}};
        if (!m_settings->item(row, 3)->text().isEmpty())
            s.insert(QStringLiteral("unit"), m_settings->item(row, 3)->text());
        settings << s;
    }
    p.insert(QStringLiteral("settings"), settings);
    QJsonArray values;
    for (int row = 0; row < m_unitValues->rowCount(); ++row) {
        QJsonObject u{{kName, m_unitValues->item(row, 1)->text()},
                      {QStringLiteral("min"), valueOf(m_unitValues->item(row, 2)->text())},
                      {QStringLiteral("max"), valueOf(m_unitValues->item(row, 3)->text())}};
        if (!m_unitValues->item(row, 4)->text().isEmpty())
            u.insert(QStringLiteral("unit"), m_unitValues->item(row, 4)->text());
        if (auto* source = qobject_cast<QComboBox*>(m_unitValues->cellWidget(row, 5)))
            u.insert(QStringLiteral("source"), source->currentData().toString());
        values << u;
    }
    p.insert(QStringLiteral("unitValues"), values);
    p.insert(QStringLiteral("steps"), m_steps->steps());
    return p;
}

QString RecipePositionForm::labelOf(const QString& name) const
{
    const ParameterMeta* meta = m_profile ? m_profile->parameter(name) : nullptr;
    return meta ? meta->label : tr("(unknown: %1)").arg(name);
}

bool RecipePositionForm::addSetting(const QString& name)
{
    const ParameterMeta* meta = m_profile ? m_profile->parameter(name) : nullptr;
    if (!meta || !BackupReader::settingNames(*m_profile).contains(name))
        return false;
    if (rowOf(m_settings, name) >= 0 || rowOf(m_unitValues, name) >= 0)
        return false;
    QJsonArray settings = position().value(QStringLiteral("settings")).toArray();
    settings << QJsonObject{{kName, name},
                            {QStringLiteral("value"), startValue(*meta)},
                            {QStringLiteral("unit"), meta->spec.unit}};
    m_filling = true;
    fillSettings(settings);
    m_filling = false;
    emit changed();
    return true;
}

bool RecipePositionForm::addUnitValue(const QString& name)
{
    const ParameterMeta* meta = m_profile ? m_profile->parameter(name) : nullptr;
    if (!meta || !BackupReader::settingNames(*m_profile).contains(name))
        return false;
    if (rowOf(m_unitValues, name) >= 0)
        return false;
    // A setting made per-unit leaves the settings: the recipe holds each name once.
    const int asSetting = rowOf(m_settings, name);
    if (asSetting >= 0) {
        m_filling = true;
        m_settings->removeRow(asSetting);
        m_filling = false;
    }
    const QJsonObject edited = position();
    const QPair<double, double> range =
        rangeOf(*meta, edited.value(QStringLiteral("variants")).toArray().first().toString());
    QJsonArray values = edited.value(QStringLiteral("unitValues")).toArray();
    values << QJsonObject{{kName, name},
                          {QStringLiteral("min"), range.first},
                          {QStringLiteral("max"), range.second},
                          {QStringLiteral("unit"), meta->spec.unit},
                          {QStringLiteral("source"), QStringLiteral("csv")}};
    m_filling = true;
    fillUnitValues(values);
    m_filling = false;
    emit changed();
    return true;
}

void RecipePositionForm::chooseSetting(bool unitValue)
{
    if (!m_profile)
        return;
    QStringList items;
    QStringList names;
    for (const QString& name : BackupReader::settingNames(*m_profile)) {
        items << tr("%1 (%2)").arg(labelOf(name), name);
        names << name;
    }
    bool ok = false;
    const QString chosen =
        QInputDialog::getItem(this, unitValue ? tr("Add a per-unit value") : tr("Add a setting"),
                              tr("Setting:"), items, 0, false, &ok);
    const int index = int(items.indexOf(chosen));
    if (!ok || index < 0)
        return;
    if (unitValue)
        addUnitValue(names.at(index));
    else
        addSetting(names.at(index));
}

void RecipePositionForm::showRow(QTableWidget* table, int row)
{
    if (row < 0 || row >= table->rowCount())
        return;
    m_tabs->setCurrentIndex(table == m_settings ? 0 : 1);
    table->setCurrentCell(row, 2);
    table->selectRow(row);
    table->scrollToItem(table->item(row, 0));
}

void RecipePositionForm::showStep(int index)
{
    m_tabs->setCurrentWidget(m_steps);
    m_steps->select(index);
}

void RecipePositionForm::removeRow(QTableWidget* table)
{
    const int row = table->currentRow();
    if (row < 0)
        return;
    table->removeRow(row);
    emit changed();
}

} // namespace opentop
