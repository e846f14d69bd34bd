#include "ui/eol/EolMenu.h"

#include "model/access/StationAccess.h"
#include "ui/eol/GoldenMeasureButton.h"
#include "ui/eol/IdentityDialog.h"
#include "ui/eol/RecipeApproveButton.h"
#include "ui/eol/RecipeEditor.h"
#include "ui/eol/ResultsBrowser.h"

#include <QAction>
#include <QMenu>
#include <QPointer>

namespace opentop {

namespace {

template <typename Window> void showOnce(QPointer<Window>& window, std::function<Window*()> make)
{
    if (!window) {
        window = make();
        window->setAttribute(Qt::WA_DeleteOnClose);
    }
    window->show();
    window->raise();
    window->activateWindow();
}

} // namespace

EolMenu::EolMenu(QMenu* menu, QWidget* window, std::function<BusDrives*()> drives)
    : QObject(window)
    , m_window(window)
    , m_drives(std::move(drives))
{
    auto editor = std::make_shared<QPointer<RecipeEditor>>();
    auto results = std::make_shared<QPointer<ResultsBrowser>>();
    m_editor = menu->addAction(tr("&Recipe editor…"), this, [this, editor] {
        auto open = [this, editor](const AccessDecision&) {
            showOnce<RecipeEditor>(*editor, [this] {
                auto* made = new RecipeEditor(m_drives, m_window);
                made->addToolbarButton(new GoldenMeasureButton(
                    m_drives, [made] { return made->document(); },
                    [made](const QJsonObject& d) { made->setDocument(d); }, made));
                made->addToolbarButton(new RecipeApproveButton(
                    m_access, [made] { return made->path(); }, made));
                return made;
            });
        };
        if (m_access && !*editor)
            IdentityDialog::ask(m_access, Privilege::EditRecipe, tr("the recipe editor"), m_window,
                                open);
        else
            open(AccessDecision{});
    });
    m_editor->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    m_results = menu->addAction(tr("Re&sults…"), this, [this, results] {
        showOnce<ResultsBrowser>(*results,
                                 [this] { return new ResultsBrowser(QString(), m_window); });
    });
    m_results->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
}

void EolMenu::setAccess(StationAccess* access)
{
    m_access = access;
}

} // namespace opentop
