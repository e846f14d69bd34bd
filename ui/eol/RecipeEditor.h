#pragma once

#include "model/eol/RecipeChecker.h"

#include <QDialog>
#include <QJsonObject>
#include <functional>

class QComboBox;
class QHBoxLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QTimer;

namespace opentop {

class BusDrives;
class GoldenRecipeSource;
class RecipePositionForm;

// The engineers' recipe editor (docs/recipe-format.md): a recipe made from a golden unit's
// drives on the bus or from a backup file, or opened from a file (one changed by hand too); the
// product, each position's variants, firmware, settings, per-unit values and steps edited; every
// change checked against the profiles at once (the same RecipeChecker as `eol recipe check`),
// each problem listed with its place; saved, signed with its checksum, only when it passes.
class RecipeEditor : public QDialog
{
    Q_OBJECT
public:
    explicit RecipeEditor(std::function<BusDrives*()> drives, QWidget* parent = nullptr);

    bool openFile(const QString& path, QString* error);
    bool newFromBackup(const QString& backupPath, const QString& product, const QString& revision,
                       QString* error);
    // Reads every setting of the drives `ids` on the bus (asynchronously, with progress and
    // cancel); `done(ok, error)` when finished.
    void newFromDrives(const QVector<int>& ids, const QString& product, const QString& revision,
                       std::function<void(bool, QString)> done);
    void setDocument(const QJsonObject& document);
    // The recipe as edited (without checksum).
    QJsonObject document();
    // Checks the recipe now: the problems (empty: it passes).
    QVector<RecipeProblem> check();
    // Saves the recipe, signed, only when it passes check; false with *error otherwise.
    bool saveTo(const QString& path, QString* error);
    QString path() const { return m_path; }

    // A button of another feature on the toolbar (the approval: RecipeApproveButton).
    void addToolbarButton(QPushButton* button);

    RecipePositionForm* positionForm() const { return m_form; }
    QListWidget* problemsList() const { return m_problems; }
    QComboBox* positionChooser() const { return m_positions; }

private:
    QWidget* makeToolbar();
    void commitPosition();
    void showPosition(int index);
    void fillPositionChooser();
    void scheduleCheck();
    void showProblem(const QString& path);
    void chooseOpen();
    void chooseSave(bool askPath);
    void say(const QString& text, bool error);

    GoldenRecipeSource* m_golden;
    QJsonObject m_document;
    int m_current = -1; // the position the form shows
    QString m_path;
    QLineEdit* m_product = nullptr;
    QLineEdit* m_revision = nullptr;
    QLineEdit* m_description = nullptr;
    QComboBox* m_positions = nullptr;
    RecipePositionForm* m_form = nullptr;
    QListWidget* m_problems = nullptr;
    QLabel* m_verdict = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_save = nullptr;
    QHBoxLayout* m_bar = nullptr;
    QTimer* m_checkTimer = nullptr;
    bool m_loading = false;
};

} // namespace opentop
