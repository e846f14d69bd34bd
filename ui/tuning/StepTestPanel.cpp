#include "ui/tuning/StepTestPanel.h"

#include "ui/tuning/NumberField.h"

#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include <algorithm>

namespace opentop {

StepTestPanel::StepTestPanel(QWidget* parent)
    : QWidget(parent)
    , m_from(NumberField::make(QStringLiteral("stepFrom"), QStringLiteral("0"), this))
    , m_to(NumberField::make(QStringLiteral("stepTo"), QStringLiteral("500"), this))
    , m_record(NumberField::make(QStringLiteral("recordTime"), QStringLiteral("1500"), this))
    , m_fromUnit(new QLabel(this))
    , m_toUnit(new QLabel(this))
    , m_note(new QLabel(this))
    , m_run(new QPushButton(tr("Run step test…"), this))
{
    m_run->setObjectName(QStringLiteral("runStep"));
    m_note->setObjectName(QStringLiteral("modeNote"));
    m_note->setWordWrap(true);
    m_note->setStyleSheet(QStringLiteral("color: #b35900;"));
    auto* form = new QFormLayout(this);
    form->addRow(tr("From:"), NumberField::withUnit(m_from, m_fromUnit, this));
    form->addRow(tr("To:"), NumberField::withUnit(m_to, m_toUnit, this));
    form->addRow(tr("Record time:"),
                 NumberField::withUnit(m_record, new QLabel(tr("ms"), this), this));
    form->addRow(m_run);
    form->addRow(m_note);
    connect(m_run, &QPushButton::clicked, this, &StepTestPanel::runClicked);
    for (QLineEdit* field : {m_from, m_to})
        connect(field, &QLineEdit::textChanged, this, &StepTestPanel::stepChanged);
}

void StepTestPanel::setSpeedUnit(const QString& unit)
{
    m_unit = unit;
    m_fromUnit->setText(unit);
    m_toUnit->setText(unit);
}

void StepTestPanel::setStep(double from, double to)
{
    m_from->setText(QString::number(from, 'g', 6));
    m_to->setText(QString::number(to, 'g', 6));
}

void StepTestPanel::setModeNote(const QString& note)
{
    m_note->setText(note);
    m_note->setVisible(!note.isEmpty());
}

void StepTestPanel::setBusy(bool busy)
{
    m_run->setEnabled(!busy);
}

double StepTestPanel::highestSpeed() const
{
    return std::max(NumberField::value(m_from).value_or(0), NumberField::value(m_to).value_or(0));
}

std::optional<TuningRunner::StepPlan> StepTestPanel::plan(QString* error) const
{
    const std::optional<double> from = NumberField::value(m_from);
    const std::optional<double> to = NumberField::value(m_to);
    const std::optional<double> record = NumberField::value(m_record);
    if (!from || !to || *from < 0 || *to < 0 || *from == *to) {
        *error = tr("Enter two different speeds of 0 %1 or more.").arg(m_unit);
        return std::nullopt;
    }
    if (!record || *record < 100 || *record > 60000) {
        *error = tr("Enter a record time of 100–60000 ms.");
        return std::nullopt;
    }
    TuningRunner::StepPlan plan;
    plan.from = *from;
    plan.to = *to;
    plan.recordMs = int(*record);
    return plan;
}

} // namespace opentop
