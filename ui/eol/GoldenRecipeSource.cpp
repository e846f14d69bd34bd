#include "ui/eol/GoldenRecipeSource.h"

#include "model/bus/BusDrives.h"
#include "model/eol/Recipe.h"
#include "model/eol/RecipeBuilder.h"
#include "model/eol/RecipeFile.h"
#include "model/eol/RecipeFromDrives.h"
#include "model/files/BackupFile.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"

#include <QFileDialog>
#include <QInputDialog>
#include <QLineEdit>
#include <QPointer>
#include <QProgressDialog>

namespace opentop {

GoldenRecipeSource::GoldenRecipeSource(std::function<BusDrives*()> drives, QWidget* window)
    : QObject(window)
    , m_drives(std::move(drives))
    , m_window(window)
{
}

bool GoldenRecipeSource::fromBackup(const QString& backupPath, const QString& product,
                                    const QString& revision, QString* error)
{
    const std::optional<BackupFile> backup =
        BackupFile::load(backupPath, ProfileRegistry::builtIn(), error);
    if (!backup)
        return false;
    const std::optional<Recipe> recipe =
        RecipeBuilder(ProfileRegistry::builtIn()).fromBackup(*backup, product, revision, error);
    if (!recipe)
        return false;
    emit made(RecipeFile::toObject(*recipe));
    emit said(tr("New recipe from %1: check the settings and the test steps' limits, then save "
                 "it.")
                  .arg(backupPath),
              false);
    return true;
}

void GoldenRecipeSource::fromDrives(const QVector<int>& ids, const QString& product,
                                    const QString& revision,
                                    std::function<void(bool, QString)> done)
{
    BusDrives* drives = m_drives ? m_drives() : nullptr;
    QVector<RecipeFromDrives::Golden> golden;
    for (int id : ids) {
        DeviceSession* session = drives ? drives->session(id) : nullptr;
        if (!session) {
            done(false, tr("machine number %1 is not a known drive on the bus; scan the bus first")
                            .arg(id));
            return;
        }
        // A variant the person chose for a drive that does not report it counts as stated.
        const QString reported =
            RecipeFromDrives::reportedVariant(session->profile(), drives->info(id));
        golden.append({id, reported, reported.isEmpty() ? session->variant() : QString()});
    }
    auto* progress = new QProgressDialog(tr("Reading the golden unit's settings…"), tr("Cancel"), 0,
                                         int(ids.size()), m_window);
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(0);
    auto* make = new RecipeFromDrives(
        drives->client(), ProfileRegistry::builtIn(),
        [drives = QPointer<BusDrives>(drives)](int slave, QString* error) -> DeviceSession* {
            DeviceSession* session = drives ? drives->session(slave) : nullptr;
            if (!session)
                *error = tr("machine number %1 is not on the bus").arg(slave);
            return session;
        },
        this);
    connect(make, &RecipeFromDrives::driveStarted, progress,
            [progress](int, int index, int) { progress->setValue(index); });
    connect(progress, &QProgressDialog::canceled, make, &RecipeFromDrives::cancel);
    make->start(golden, product, revision, qEnvironmentVariable("USER"),
                [this, make, progress, done](const RecipeFromDrives::Result& r) {
                    make->deleteLater();
                    progress->deleteLater();
                    if (!r.recipe) {
                        done(false, r.failure == RecipeFromDrives::Failure::Cancelled
                                        ? tr("cancelled: no recipe was made")
                                        : r.problems.join(QStringLiteral("; ")));
                        return;
                    }
                    emit made(RecipeFile::toObject(*r.recipe));
                    done(true, QString());
                });
}

bool GoldenRecipeSource::askProductAndRevision(QString* product, QString* revision)
{
    bool ok = false;
    *product = QInputDialog::getText(m_window, tr("New recipe"), tr("Product name:"),
                                     QLineEdit::Normal, *product, &ok)
                   .trimmed();
    if (!ok || product->isEmpty())
        return false;
    *revision = QInputDialog::getText(m_window, tr("New recipe"), tr("Revision:"),
                                      QLineEdit::Normal, QStringLiteral("A"), &ok)
                    .trimmed();
    return ok && !revision->isEmpty();
}

void GoldenRecipeSource::chooseBackup(const QString& product)
{
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Golden unit's backup file"),
                                                      QString(), tr("Backups (*.json)"));
    QString name = product, revision, error;
    if (path.isEmpty() || !askProductAndRevision(&name, &revision))
        return;
    if (!fromBackup(path, name, revision, &error))
        emit said(error, true);
}

void GoldenRecipeSource::chooseDrives(const QString& product)
{
    BusDrives* drives = m_drives ? m_drives() : nullptr;
    if (!drives || drives->slaves().isEmpty()) {
        emit said(tr("No drives on the bus: connect and scan first."), true);
        return;
    }
    QStringList numbers;
    for (int s : drives->slaves())
        numbers << QString::number(s);
    bool ok = false;
    const QString text =
        QInputDialog::getText(m_window, tr("New recipe from drives"),
                              tr("Machine numbers of the golden unit's drives (found: %1):")
                                  .arg(numbers.join(QStringLiteral(", "))),
                              QLineEdit::Normal, numbers.join(QLatin1Char(',')), &ok);
    if (!ok)
        return;
    QVector<int> ids;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool isNumber = false;
        const int id = part.trimmed().toInt(&isNumber);
        if (!isNumber || id < 1 || id > 247) {
            emit said(tr("\"%1\" is not a machine number (1–247)").arg(part.trimmed()), true);
            return;
        }
        ids << id;
    }
    QString name = product, revision;
    if (ids.isEmpty() || !askProductAndRevision(&name, &revision))
        return;
    fromDrives(ids, name, revision, [this](bool done, const QString& error) {
        emit said(done ? tr("New recipe from the drives on the bus: check the settings and the "
                            "test steps' limits, then save it.")
                       : error,
                  !done);
    });
}

} // namespace opentop
