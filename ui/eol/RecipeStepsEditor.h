#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QWidget>

class QFormLayout;
class QGroupBox;
class QPushButton;
class QTableWidget;

namespace opentop {

class Profile;

// A position's test steps as a line engineer edits them (docs/recipe-format.md): the steps in
// order as a table (add, remove, move), and the selected step's fields as a form by its type,
// a hold's limits as a table of parameter, statistic, lower, upper and unit. It edits the
// steps' JSON only; whether they are valid is the recipe checker's word, shown by the editor
// at every change. A number field left empty is a key left out (an optional target speed or
// deceleration: the drive's own); text that is not a number is kept, for the checker to name.
class RecipeStepsEditor : public QWidget
{
    Q_OBJECT
public:
    explicit RecipeStepsEditor(QWidget* parent = nullptr);

    // The family's profile names the parameters a limit or a read may take, with their units.
    void setProfile(const Profile* profile) { m_profile = profile; }
    void setSteps(const QJsonArray& steps);
    QJsonArray steps() const { return m_steps; }

    QTableWidget* table() const { return m_table; }
    QGroupBox* detail() const { return m_detail; }
    // Selects step `index` and shows its fields (a checker problem's step).
    void select(int index);
    // Adds a step of `type` ("hold", "stop", ...) after the selected one, selected.
    void addStep(const QString& type);

    // The step types in the order a run usually takes them, and their names for people.
    static QStringList types();
    static QString typeText(const QString& type);

signals:
    void changed();

private:
    void fillTable();
    void fillRow(int row);
    void showDetail();
    void removeSelected();
    void moveSelected(int by);
    int selected() const;
    // The selected step's field `key` becomes `value` (undefined: left out).
    void setField(const QString& key, const QJsonValue& value);
    void addNumberField(QFormLayout* form, const QString& label, const QString& key,
                        const QString& unit, const QString& empty = QString());
    void addTextField(QFormLayout* form, const QString& label, const QString& key,
                      const QString& placeholder = QString());
    void addParameterField(QFormLayout* form, const QString& key);
    QString unitOf(const QString& parameter) const;

    const Profile* m_profile = nullptr;
    QJsonArray m_steps;
    QTableWidget* m_table;
    QGroupBox* m_detail;
    QWidget* m_fields = nullptr; // the selected step's form, rebuilt when another is selected
    QPushButton* m_remove;
    QPushButton* m_up;
    QPushButton* m_down;
    bool m_filling = false;
};

} // namespace opentop
