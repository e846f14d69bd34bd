#pragma once

#include "model/profile/SpeedDisplay.h"
#include "ui/workspace/ParameterPage.h"

#include <QHash>
#include <QVector>

class QComboBox;
class QFormLayout;
class QLabel;
class QSpinBox;

namespace opentop {

class ParameterField;

// The DBU's speed display settings (manual 7-1-4, 12-10): the unit, the fields that unit uses
// (the others are disabled), decimals, update time and the ro-0…ro-3 corrections, with a
// preview of what the drive's display shows for a chosen motor speed once the pending edits
// are written. The conversion itself is SpeedDisplay's (docs/speed-display.md).
class SpeedUnitsPage : public ParameterPage
{
    Q_OBJECT
public:
    explicit SpeedUnitsPage(DeviceParameters* parameters, QWidget* parent = nullptr);

    QStringList parameterNames() const override;
    ParameterField* field(const QString& name) const { return m_fields.value(name); }

    // Preview input: motor speed in r/min (default 1500) and direction.
    void setPreviewSpeed(int rpm, bool reverse = false);
    // What the preview shows, as the drive's 5-digit panel does (SpeedDisplay::panelText):
    // "1500.0" and "r/min"; "-----" and no unit when not computable.
    QString previewText() const;
    QString previewUnit() const;

protected:
    void parameterChanged(const QString& name) override;

private:
    void addRow(QFormLayout* form, const QString& name, const QString& label,
                QLabel* extraUnit = nullptr);
    void updateEnabled();
    void updatePreview();
    std::optional<double> valueAsWritten(const QString& name) const;

    SpeedDisplay::Names m_names;
    QStringList m_parameterNames;
    QHash<QString, ParameterField*> m_fields;
    QHash<QString, QLabel*> m_labels;
    QHash<QString, QVector<quint16>> m_typed; // accepted text typed but not yet confirmed
    QLabel* m_distanceUnit;
    QSpinBox* m_speed;
    QComboBox* m_direction;
    QLabel* m_display;
    QLabel* m_displayUnit;
    QLabel* m_previewNote;
};

} // namespace opentop
