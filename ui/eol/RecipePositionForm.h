#pragma once

#include <QJsonObject>
#include <QWidget>

class QLabel;
class QLineEdit;
class QSpinBox;
class QTabWidget;
class QTableWidget;

namespace opentop {

class Profile;
class RecipeStepsEditor;

// One position of a recipe as the editor shows it: machine number, name, allowed variants and
// firmware, the settings and per-unit values as tables with labels and units from the profile,
// and the test steps (RecipeStepsEditor). It only edits the position's JSON (docs/
// recipe-format.md); whether it is valid is the recipe checker's word (RecipeEditor).
class RecipePositionForm : public QWidget
{
    Q_OBJECT
public:
    explicit RecipePositionForm(QWidget* parent = nullptr);

    void setPosition(const QJsonObject& position);
    // The position as edited.
    QJsonObject position() const;

    QTableWidget* settingsTable() const { return m_settings; }
    QTableWidget* unitValuesTable() const { return m_unitValues; }
    RecipeStepsEditor* stepsEditor() const { return m_steps; }
    // Brings step `index` into view, selected, on its tab.
    void showStep(int index);
    // Adds a setting of the position's profile (its default value) or a per-unit value (its
    // widest allowed range; a setting of that name becomes per-unit); false when the name is not
    // a setting of the profile or is already there.
    bool addSetting(const QString& name);
    bool addUnitValue(const QString& name);
    // Brings a row of one of the tables into view, selected, on its tab.
    void showRow(QTableWidget* table, int row);

signals:
    void changed();

private:
    void fillSettings(const QJsonArray& settings);
    void fillUnitValues(const QJsonArray& values);
    void chooseSetting(bool unitValue);
    void removeRow(QTableWidget* table);
    QString labelOf(const QString& name) const;

    QJsonObject m_position; // as last set: the keys the form does not show are kept
    const Profile* m_profile = nullptr;
    QSpinBox* m_machineNumber = nullptr;
    QLineEdit* m_name = nullptr;
    QLabel* m_family = nullptr;
    QLineEdit* m_variants = nullptr;
    QLineEdit* m_firmware = nullptr;
    QTableWidget* m_settings = nullptr;
    QTableWidget* m_unitValues = nullptr;
    RecipeStepsEditor* m_steps = nullptr;
    QTabWidget* m_tabs = nullptr;
    bool m_filling = false;
};

} // namespace opentop
