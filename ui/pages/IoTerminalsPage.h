#pragma once

#include "model/profile/ValueContext.h"
#include "ui/workspace/ParameterPage.h"

#include <QHash>
#include <optional>

class QGridLayout;
class QLabel;
class QPushButton;

namespace opentop {

class ParameterField;

// The DBU's I/O terminals drawn like the connectors: inputs X0–X3 on CN5 at the left, outputs
// Y0/Y1 on CN6 at the right, each with its function chooser and what the function does. The
// control mode and control priority sit on top. The input function codes differ between Mode1
// and Mode2, so the choosers follow the mode that will be in force once the pending edits are
// written, and inputs whose function is not valid in that mode are flagged.
class IoTerminalsPage : public ParameterPage
{
    Q_OBJECT
public:
    explicit IoTerminalsPage(DeviceParameters* parameters, QWidget* parent = nullptr);

    QStringList parameterNames() const override { return m_names; }

    ParameterField* field(const QString& name) const { return m_fields.value(name); }
    QString description(const QString& name) const;
    // Input terminals (parameter names) whose function must be chosen again before writing.
    QStringList invalidTerminals() const { return m_invalid; }
    QString flagText() const;
    // What the choosers follow: the context with pending edits applied (a pending mode).
    ValueContext editContext() const;
    // Gives each flagged input the default function of the mode being switched to.
    void useModeDefaults();

    QString writeBlocker() const override;

protected:
    void parameterChanged(const QString& name) override;

private:
    void addTerminal(QGridLayout* grid, int row, const QString& pins, const QString& terminal,
                     const QString& name);
    void addCommon(QGridLayout* grid, int row, int pin, const QString& terminal,
                   const QString& text);
    std::optional<qint64> shownRaw(const QString& name) const;
    QString modeLabel(std::optional<qint64> raw) const;
    void updateDescription(const QString& name);
    void updateMode();

    QStringList m_names;
    QStringList m_inputs;
    QHash<QString, ParameterField*> m_fields;
    QHash<QString, QLabel*> m_descriptions;
    QStringList m_invalid;
    QLabel* m_modeNote = nullptr;
    QLabel* m_flag = nullptr;
    QPushButton* m_useDefaults = nullptr;
};

} // namespace opentop
