#include "ui/tuning/NumberField.h"

#include <QDoubleValidator>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>

namespace opentop {

QLineEdit* NumberField::make(const QString& name, const QString& text, QWidget* parent)
{
    auto* field = new QLineEdit(text, parent);
    field->setObjectName(name);
    auto* validator = new QDoubleValidator(field);
    validator->setLocale(QLocale::c());
    field->setValidator(validator);
    field->setMaximumWidth(90);
    return field;
}

QWidget* NumberField::withUnit(QWidget* field, QLabel* unit, QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(field);
    row->addWidget(unit);
    row->addStretch();
    return box;
}

std::optional<double> NumberField::value(const QLineEdit* field)
{
    bool ok = false;
    const double v = QLocale::c().toDouble(field->text().trimmed(), &ok);
    return ok ? std::optional<double>(v) : std::nullopt;
}

QString NumberField::text(double v)
{
    return QLocale().toString(v, 'g', 6);
}

} // namespace opentop
