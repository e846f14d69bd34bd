#pragma once

#include <QString>
#include <optional>

class QLabel;
class QLineEdit;
class QWidget;

namespace opentop {

// The tuning page's number fields: C-locale numbers, a unit label beside each.
class NumberField
{
public:
    static QLineEdit* make(const QString& name, const QString& text, QWidget* parent);
    // The field with its unit beside it, in a row of its own.
    static QWidget* withUnit(QWidget* field, QLabel* unit, QWidget* parent);
    static std::optional<double> value(const QLineEdit* field);
    // A number for people, in the user's locale.
    static QString text(double v);
};

} // namespace opentop
