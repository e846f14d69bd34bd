#include "ui/eol/RecipeStepsEditor.h"

#include "model/eol/Recipe.h"
#include "model/eol/RecipeStepKinds.h"

#include "model/profile/Profile.h"
#include "ui/eol/RecipeLimitsTable.h"
#include "ui/eol/RecipeNumberText.h"
#include "ui/widgets/PlainText.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace opentop {

namespace {

const QString kType = QStringLiteral("type");
const QString kLimits = QStringLiteral("limits");
const QString kParameter = QStringLiteral("parameter");
const QString kUnit = QStringLiteral("unit");

QTableWidgetItem* fixedItem(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

} // namespace

RecipeStepsEditor::RecipeStepsEditor(QWidget* parent)
    : QWidget(parent)
    , m_table(new QTableWidget(0, 3, this))
    , m_detail(new QGroupBox(this))
{
    m_table->setObjectName(QStringLiteral("recipeSteps"));
    m_table->setHorizontalHeaderLabels({tr("#"), tr("Step"), tr("What it does")});
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);

    auto* add = new QPushButton(tr("Add step"), this);
    auto* menu = new QMenu(add);
    for (const QString& type : types())
        menu->addAction(typeText(type), this, [this, type] { addStep(type); });
    add->setMenu(menu);
    m_remove = new QPushButton(tr("Remove"), this);
    m_up = new QPushButton(tr("Move up"), this);
    m_down = new QPushButton(tr("Move down"), this);
    connect(m_remove, &QPushButton::clicked, this, &RecipeStepsEditor::removeSelected);
    connect(m_up, &QPushButton::clicked, this, [this] { moveSelected(-1); });
    connect(m_down, &QPushButton::clicked, this, [this] { moveSelected(1); });
    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {add, m_remove, m_up, m_down})
        buttons->addWidget(b);
    buttons->addStretch(1);

    new QVBoxLayout(m_detail);
    auto* list = new QVBoxLayout;
    list->addWidget(m_table, 1);
    list->addLayout(buttons);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(list, 2);
    layout->addWidget(m_detail, 3); // a hold's limits need the room
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &RecipeStepsEditor::showDetail);
    showDetail();
}

QStringList RecipeStepsEditor::types()
{
    return Recipe::stepTypeNames(); // the step table's, in its order
}

QString RecipeStepsEditor::typeText(const QString& type)
{
    const RecipeStepKinds::Kind* kind = RecipeStepKinds::of(type);
    if (!kind)
        return tr("(unknown step: %1)").arg(type);
    QString title = RecipeStepKinds::title(kind->type);
    if (!title.isEmpty())
        title[0] = title[0].toUpper(); // a list entry starts with a capital
    return title;
}

void RecipeStepsEditor::setSteps(const QJsonArray& steps)
{
    m_steps = steps;
    fillTable();
    select(steps.isEmpty() ? -1 : 0);
}

void RecipeStepsEditor::fillTable()
{
    const QSignalBlocker block(m_table);
    m_table->setRowCount(int(m_steps.size()));
    for (int row = 0; row < m_steps.size(); ++row)
        fillRow(row);
    m_table->resizeColumnToContents(0);
    m_table->resizeColumnToContents(1);
}

void RecipeStepsEditor::fillRow(int row)
{
    const QJsonObject step = m_steps.at(row).toObject();
    m_table->setItem(row, 0, fixedItem(QString::number(row + 1)));
    m_table->setItem(row, 1, fixedItem(typeText(step.value(kType).toString())));
    QTableWidgetItem* what = fixedItem(RecipeStepKinds::summary(step, m_profile));
    what->setToolTip(PlainText::asWritten(what->text())); // whole, when the column is narrower
    m_table->setItem(row, 2, what);
}

int RecipeStepsEditor::selected() const
{
    const QList<QTableWidgetItem*> items = m_table->selectedItems();
    return items.isEmpty() ? -1 : items.first()->row();
}

void RecipeStepsEditor::select(int index)
{
    if (index < 0 || index >= m_table->rowCount()) {
        m_table->clearSelection();
        showDetail();
        return;
    }
    m_table->selectRow(index);
    m_table->scrollToItem(m_table->item(index, 0));
    showDetail(); // also when it was selected already: the fields are the step's as it is
}

void RecipeStepsEditor::addStep(const QString& type)
{
    const int at = selected() < 0 ? int(m_steps.size()) : selected() + 1;
    QJsonObject step{{kType, type}};
    if (type == QLatin1String("start"))
        step.insert(QStringLiteral("direction"), QStringLiteral("cw"));
    if (type == QLatin1String("select"))
        step.insert(QStringLiteral("spno"), 1);
    if (type == QLatin1String("hold"))
        step.insert(kLimits, QJsonArray());
    m_steps.insert(at, step);
    fillTable();
    select(at);
    emit changed();
}

void RecipeStepsEditor::removeSelected()
{
    const int row = selected();
    if (row < 0)
        return;
    m_steps.removeAt(row);
    fillTable();
    select(std::min(row, int(m_steps.size()) - 1));
    emit changed();
}

void RecipeStepsEditor::moveSelected(int by)
{
    const int row = selected();
    const int to = row + by;
    if (row < 0 || to < 0 || to >= m_steps.size())
        return;
    const QJsonValue step = m_steps.at(row);
    m_steps.removeAt(row);
    m_steps.insert(to, step);
    fillTable();
    select(to);
    emit changed();
}

void RecipeStepsEditor::setField(const QString& key, const QJsonValue& value)
{
    const int row = selected();
    if (row < 0 || m_filling)
        return;
    QJsonObject step = m_steps.at(row).toObject();
    if (value.isUndefined())
        step.remove(key);
    else
        step.insert(key, value);
    m_steps.replace(row, step);
    fillRow(row);
    emit changed();
}

void RecipeStepsEditor::showDetail()
{
    const int row = selected();
    m_remove->setEnabled(row >= 0);
    m_up->setEnabled(row > 0);
    m_down->setEnabled(row >= 0 && row + 1 < m_steps.size());
    if (m_fields) {
        // Later: this may run inside a signal of one of its fields.
        m_fields->setParent(nullptr);
        m_fields->deleteLater();
    }
    m_fields = new QWidget(m_detail);
    m_detail->layout()->addWidget(m_fields);
    auto* form = new QFormLayout(m_fields);
    if (row < 0) {
        m_detail->setTitle(tr("No step selected"));
        form->addRow(new QLabel(tr("Add a step, or select one to edit it."), m_fields));
        return;
    }
    m_filling = true;
    const QJsonObject step = m_steps.at(row).toObject();
    const QString type = step.value(kType).toString();
    m_detail->setTitle(tr("Step %1: %2").arg(row + 1).arg(typeText(type)));
    // The fields are the step table's (RecipeStepKinds): one widget per kind of value.
    const QString speedUnit = step.value(kUnit).toString();
    const RecipeStepKinds::Kind* kind = RecipeStepKinds::of(type);
    using FieldKind = RecipeStepKinds::Field::Kind;
    for (const RecipeStepKinds::Field& f :
         kind ? kind->fields : QVector<RecipeStepKinds::Field>()) {
        const QString key = QString::fromLatin1(f.key);
        const QString label = RecipeStepKinds::fieldLabel(f);
        switch (f.kind) {
        case FieldKind::Integer: {
            auto* spin = new QSpinBox(m_fields);
            spin->setObjectName(QStringLiteral("step_") + key);
            spin->setRange(int(f.min), int(f.max));
            if (key == QLatin1String("spno"))
                spin->setPrefix(QStringLiteral("SPno"));
            spin->setValue(step.value(key).toInt(int(f.min)));
            connect(spin, &QSpinBox::valueChanged, this, [this, key](int v) { setField(key, v); });
            form->addRow(label, spin);
            break;
        }
        case FieldKind::Number:
            addNumberField(form, label, key,
                           QLatin1String(f.unit) == QLatin1String("s")
                               ? tr("s")
                               : (type == QLatin1String("read") ? QString() : speedUnit),
                           RecipeStepKinds::fieldEmpty(f));
            break;
        case FieldKind::Direction: {
            auto* direction = new QComboBox(m_fields);
            direction->setObjectName(QStringLiteral("step_") + key);
            direction->addItem(tr("CW"), QStringLiteral("cw"));
            direction->addItem(tr("CCW"), QStringLiteral("ccw"));
            direction->setCurrentIndex(
                std::max(0, direction->findData(step.value(key).toString())));
            connect(direction, &QComboBox::currentIndexChanged, this,
                    [this, direction, key] { setField(key, direction->currentData().toString()); });
            form->addRow(label, direction);
            break;
        }
        case FieldKind::Unit:
        case FieldKind::Text:
            addTextField(form, label, key, RecipeStepKinds::fieldEmpty(f));
            break;
        case FieldKind::Parameter:
            addParameterField(form, key);
            break;
        case FieldKind::Limits: {
            auto* limits =
                new RecipeLimitsTable(m_profile, step.value(kLimits).toArray(), m_fields);
            connect(limits, &RecipeLimitsTable::changed, this,
                    [this, limits] { setField(kLimits, limits->limits()); });
            form->addRow(limits);
            break;
        }
        }
    }
    if (!kind || kind->fields.isEmpty())
        form->addRow(new QLabel(tr("This step has no settings."), m_fields));
    m_filling = false;
}

void RecipeStepsEditor::addNumberField(QFormLayout* form, const QString& label, const QString& key,
                                       const QString& unit, const QString& empty)
{
    const int row = selected();
    auto* edit =
        new QLineEdit(RecipeNumberText::text(m_steps.at(row).toObject().value(key)), m_fields);
    edit->setObjectName(QStringLiteral("step_") + key);
    edit->setPlaceholderText(empty);
    connect(edit, &QLineEdit::textEdited, this,
            [this, key](const QString& text) { setField(key, RecipeNumberText::value(text)); });
    auto* line = new QHBoxLayout;
    line->addWidget(edit, 1);
    if (!unit.isEmpty())
        line->addWidget(new QLabel(unit, m_fields));
    form->addRow(label, line);
}

void RecipeStepsEditor::addTextField(QFormLayout* form, const QString& label, const QString& key,
                                     const QString& placeholder)
{
    const int row = selected();
    auto* edit = new QLineEdit(m_steps.at(row).toObject().value(key).toString(), m_fields);
    edit->setObjectName(QStringLiteral("step_") + key);
    edit->setPlaceholderText(placeholder);
    connect(edit, &QLineEdit::textEdited, this, [this, key](const QString& text) {
        setField(key, text.isEmpty() ? QJsonValue(QJsonValue::Undefined) : QJsonValue(text));
    });
    form->addRow(label, edit);
}

void RecipeStepsEditor::addParameterField(QFormLayout* form, const QString& key)
{
    const QString current = m_steps.at(selected()).toObject().value(key).toString();
    auto* choice = new QComboBox(m_fields);
    choice->setObjectName(QStringLiteral("step_") + key);
    if (m_profile)
        for (const ParameterMeta& p : m_profile->parameters)
            if (p.isReadable() && p.kind != QLatin1String("reserved"))
                choice->addItem(tr("%1 (%2)").arg(p.label, p.name), p.name);
    if (!current.isEmpty() && choice->findData(current) < 0)
        choice->addItem(tr("(unknown: %1)").arg(current), current);
    choice->setCurrentIndex(current.isEmpty() ? -1 : choice->findData(current));
    connect(choice, &QComboBox::currentIndexChanged, this, [this, choice, key] {
        const QString name = choice->currentData().toString();
        setField(key, name);
        // The unit a limit must be given in is the parameter's own.
        if (!m_steps.at(selected()).toObject().contains(QStringLiteral("equals")))
            setField(kUnit, unitOf(name));
        showDetail();
    });
    form->addRow(tr("Parameter:"), choice);
}

QString RecipeStepsEditor::unitOf(const QString& parameter) const
{
    const ParameterMeta* meta = m_profile ? m_profile->parameter(parameter) : nullptr;
    return meta ? meta->spec.canonicalUnit : QString(); // as recipe files give units
}

} // namespace opentop
