#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;

namespace opentop {

class DeviceParameters;

// One parameter as an input field: a drop-down for enumerations, a line edit for numbers and
// text, with the unit beside it, help and allowed values in the tooltip. Input is checked as it
// is typed (a refused value is marked red and says what is allowed) and becomes a pending edit
// when accepted; pending, failed and read-only states are visible. Device values update the
// field only while the user is not editing it.
class ParameterField : public QWidget
{
    Q_OBJECT
public:
    ParameterField(DeviceParameters* parameters, const QString& name, QWidget* parent = nullptr);

    QString parameterName() const { return m_name; }
    QWidget* editor() const;
    // Shows the current device value / pending edit / state. Called on entryChanged.
    void sync();
    // What the last typed text was refused for; empty when accepted.
    QString problem() const { return m_problem; }
    // Programmatic input, as if typed and confirmed (tests, multi-field editors).
    void enter(const QString& text);

private:
    void commit(const QString& text);
    void check(const QString& text);
    void applyStyle();

    DeviceParameters* m_parameters;
    QString m_name;
    QComboBox* m_combo = nullptr;
    QLineEdit* m_edit = nullptr;
    QLabel* m_unit;
    QString m_problem;
    bool m_syncing = false;
};

} // namespace opentop
