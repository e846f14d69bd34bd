#include "ui/eol/RecipeApproveButton.h"

#include "model/access/StationAccess.h"
#include "model/eol/RecipeFile.h"
#include "model/io/DisplayText.h"
#include "ui/eol/IdentityDialog.h"
#include "ui/widgets/PlainText.h"

#include <QDir>
#include <QMessageBox>

namespace opentop {

RecipeApproveButton::RecipeApproveButton(StationAccess* access, std::function<QString()> savedPath,
                                         QWidget* parent)
    : QPushButton(tr("Approve…"), parent)
    , m_access(access)
    , m_savedPath(std::move(savedPath))
{
    setObjectName(QStringLiteral("approveRecipe"));
    setToolTip(tr("Approve the saved recipe for the line (an engineer): stations with users run "
                  "only approved recipes"));
    connect(this, &QPushButton::clicked, this, &RecipeApproveButton::approve);
}

void RecipeApproveButton::approve()
{
    const QString path = m_savedPath();
    QString error;
    QString checksum;
    const std::optional<Recipe> recipe =
        path.isEmpty() ? std::nullopt : RecipeFile::load(path, &error, &checksum);
    if (!recipe) {
        PlainText::warning(
            window(), tr("Approve recipe"),
            path.isEmpty()
                ? tr("Save the recipe first: what is approved is the saved "
                     "file's checksum.")
                : tr("%1 cannot be approved: %2").arg(QDir::toNativeSeparators(path), error));
        return;
    }
    if (!m_access || m_access->state() == StationAccess::State::Unmanaged) {
        QMessageBox::information(window(), tr("Approve recipe"),
                                 tr("This station has no users: an approval names its approver. "
                                    "Set up users with opentop-cli eol user add."));
        return;
    }
    auto* dialog = new IdentityDialog(
        m_access, Privilege::ApproveRecipe,
        tr("approve %1 rev. %2")
            .arg(DisplayText::escaped(recipe->product), DisplayText::escaped(recipe->revision)),
        window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    const QString product = recipe->product;
    const QString revision = recipe->revision;
    dialog->setCheck(
        [this, product, revision, checksum](const Identity& who, QObject* context,
                                            std::function<void(const AccessDecision&)> done) {
            if (m_access)
                m_access->approve(who, product, revision, checksum, context, std::move(done));
        });
    connect(dialog, &IdentityDialog::granted, this,
            [this, product, revision](const AccessDecision& d) {
                PlainText::information(
                    window(), tr("Approve recipe"),
                    tr("%1 rev. %2 is approved by %3: stations run it.")
                        .arg(DisplayText::escaped(product), DisplayText::escaped(revision),
                             DisplayText::escaped(d.user ? d.user->name : QString())));
            });
    dialog->open();
}

} // namespace opentop
