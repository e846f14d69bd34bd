#pragma once

#include "model/profile/ValueContext.h"

#include <QWidget>
#include <functional>

class QComboBox;
class QLabel;
class QLineEdit;

namespace opentop {

class DeviceParameters;

// One parameter as an input field: a drop-down for enumerations, a line edit for numbers and
// text, with the unit beside it, help and allowed values in the tooltip. Input is checked as it
// is typed; a refused value is marked red and a message under the field says, in words, what
// is allowed. A confirmed text becomes an edit of the model (pending, or invalid and kept so it
// can be corrected or reverted); pending, failed and read-only states are visible. Device
// values update the field only while the user is not editing it.
class ParameterField : public QWidget
{
    Q_OBJECT
public:
    ParameterField(DeviceParameters* parameters, const QString& name, QWidget* parent = nullptr);
    ~ParameterField() override;

    QString parameterName() const { return m_name; }
    QWidget* editor() const;
    // Shows the current device value / pending edit / state. Called on entryChanged.
    void sync();
    // What the text in the field is refused for (or why its write failed); empty when fine.
    // It is also the text of the message under the field.
    QString problem() const;
    // An allowed value outside the recommended range (typed, pending or on the drive): the
    // warning shown at the field, naming the recommended range; empty otherwise.
    QString warning() const;
    QLabel* messageLabel() const { return m_message; }
    // The message shown for the field now (under it, or by the page when outside).
    QString messageText() const;
    bool messageIsProblem() const { return !problem().isEmpty(); }
    // In a grid the message goes to the page's own line (messageChanged) instead of under the
    // field, so that a message never moves the rows below under the mouse.
    void setMessageOutside(bool outside);
    // Programmatic input, as if typed and confirmed (tests, multi-field editors).
    void enter(const QString& text);
    // Where allowed values and drop-down options come from; by default the session's context
    // (device values). A page whose choices must follow another parameter's pending edit (the
    // I/O functions of a pending control mode) supplies its own. Re-syncs the field.
    void setContextProvider(std::function<ValueContext()> provider);

signals:
    void messageChanged();

private:
    void commit(const QString& text);
    void commitNow(const QString& text);
    void check(const QString& text);
    void applyStyle();
    ValueContext context() const;

    DeviceParameters* m_parameters;
    QString m_name;
    QComboBox* m_combo = nullptr;
    QLineEdit* m_edit = nullptr;
    QLabel* m_unit;
    QLabel* m_message;
    QString m_problem;       // refusal of text being typed, before it is confirmed
    QString m_typingWarning; // the recommendation warning of text being typed
    bool m_syncing = false;
    bool m_askingVariant = false; // the variant question is open for an edit of this field
    bool m_messageOutside = false;
    std::function<ValueContext()> m_contextProvider;
};

} // namespace opentop
