#include "ui/bus/BusListMenu.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveName.h"
#include "ui/bus/BusPanel.h"
#include "ui/bus/DriveLineDialog.h"
#include "ui/bus/VariantMenu.h"
#include "ui/widgets/PlainText.h"

#include <QInputDialog>
#include <QLineEdit>
#include <QMenu>

namespace opentop {

BusListMenu::BusListMenu(BusPanel* panel, BusDrives* drives)
    : QObject(panel)
    , m_panel(panel)
    , m_drives(drives)
{
}

QMenu* BusListMenu::menuFor(const QVector<int>& slaves, QWidget* parent)
{
    auto* menu = new QMenu(parent);
    if (slaves.isEmpty())
        return menu;
    VariantMenu::add(menu, m_drives, slaves);
    if (slaves.size() == 1) {
        QAction* name = menu->addAction(tr("&Name this machine…"));
        name->setObjectName(QStringLiteral("nameMachine"));
        name->setShortcut(QKeySequence(Qt::Key_F2));
        connect(name, &QAction::triggered, this,
                [this, slave = slaves.first()] { askName(slave); });
    }
    QAction* identify = menu->addAction(tr("&Identify again"));
    connect(identify, &QAction::triggered, this, [this, slaves] {
        for (int s : slaves)
            m_panel->addDrive(s);
    });
    identify->setEnabled(!m_panel->isScanning());
    if (slaves.size() == 1) {
        QAction* line = DriveLineDialog::addMenuAction(
            menu, m_drives, slaves.first(), [this](int slave) { m_panel->addDrive(slave); });
        line->setEnabled(line->isEnabled() && !m_panel->isScanning());
    }
    QAction* remove = menu->addAction(tr("&Remove from list"));
    connect(remove, &QAction::triggered, this, [this, slaves] {
        for (int s : slaves)
            m_drives->remove(s);
    });
    remove->setEnabled(!m_panel->isScanning());
    return menu;
}

void BusListMenu::askName(int slave)
{
    // Asked again with the text as typed until the model takes it or the user cancels.
    QString text = m_drives->name(slave);
    QString problem;
    for (;;) {
        QString label = tr("Name of %1 (up to %2 characters; empty removes the name):")
                            .arg(m_drives->label(slave))
                            .arg(DriveName::kMaxLength);
        if (!problem.isEmpty())
            label = problem + QStringLiteral("\n\n") + label;
        bool ok = false;
        // The name as it is and as typed, quoted in the label and the problem.
        text = QInputDialog::getText(m_panel, tr("Name this machine"), PlainText::asWritten(label),
                                     QLineEdit::Normal, text, &ok);
        if (!ok)
            return;
        problem = m_drives->setName(slave, text);
        if (problem.isEmpty()) {
            emit message(m_drives->name(slave).isEmpty()
                             ? tr("Machine number %1 has no name now.").arg(slave)
                             : tr("Machine number %1 is now named %2.")
                                   .arg(slave)
                                   .arg(m_drives->name(slave)));
            return;
        }
    }
}

} // namespace opentop
