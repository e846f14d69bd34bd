#pragma once

#include <QJsonObject>
#include <QObject>
#include <QVector>
#include <functional>

class QWidget;

namespace opentop {

class BusDrives;

// Where the recipe editor's new recipes come from: a golden unit, either its drives on the bus
// (every setting read with progress and Cancel; RecipeFromDrives proves the variants) or its
// backup file (RecipeBuilder). Asks which drives or which file, the product and its revision;
// the new recipe is handed over as a document (made), what happened is said (said).
class GoldenRecipeSource : public QObject
{
    Q_OBJECT
public:
    // `window`: the editor its questions and progress show over.
    GoldenRecipeSource(std::function<BusDrives*()> drives, QWidget* window);

    bool fromBackup(const QString& backupPath, const QString& product, const QString& revision,
                    QString* error);
    // Reads every setting of the drives `ids` on the bus (asynchronously, with progress and
    // cancel); `done(ok, error)` when finished, after made() when a recipe was made.
    void fromDrives(const QVector<int>& ids, const QString& product, const QString& revision,
                    std::function<void(bool, QString)> done);
    // The toolbar's "New from…" buttons: the questions, then the recipe. `product`: the name
    // offered first.
    void chooseBackup(const QString& product);
    void chooseDrives(const QString& product);

signals:
    // A new recipe, not saved anywhere yet.
    void made(const QJsonObject& document);
    void said(const QString& text, bool error);

private:
    bool askProductAndRevision(QString* product, QString* revision);

    std::function<BusDrives*()> m_drives;
    QWidget* m_window;
};

} // namespace opentop
