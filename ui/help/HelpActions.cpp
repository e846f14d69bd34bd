#include "ui/help/HelpActions.h"

#include "ui/help/AboutDialog.h"
#include "ui/help/ShortcutsDialog.h"
#include "ui/help/UserGuideDialog.h"

#include <QAction>
#include <QApplication>
#include <QMainWindow>
#include <QMenu>

namespace opentop {

HelpActions::HelpActions(QMainWindow* window, QMenu* menu)
    : QObject(window)
    , m_window(window)
{
    m_guide = menu->addAction(tr("&User guide"), this,
                              [this] { showOnce<UserGuideDialog>("userGuideDialog", m_window); });
    m_guide->setShortcut(QKeySequence::HelpContents);
    m_shortcuts = menu->addAction(tr("&Keyboard shortcuts"), this, [this] {
        showOnce<ShortcutsDialog>("shortcutsDialog", m_window, m_window);
    });
    menu->addSeparator();
    m_about = menu->addAction(tr("&About OpenTOP"), this,
                              [this] { showOnce<AboutDialog>("aboutDialog", m_window); });
    m_about->setMenuRole(QAction::AboutRole);
    QAction* aboutQt = menu->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    aboutQt->setMenuRole(QAction::AboutQtRole);
}

template <typename Dialog, typename... Args>
void HelpActions::showOnce(const char* name, Args... args)
{
    auto* dialog =
        m_window->findChild<Dialog*>(QString::fromLatin1(name), Qt::FindDirectChildrenOnly);
    if (!dialog) {
        dialog = new Dialog(args...);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

} // namespace opentop
