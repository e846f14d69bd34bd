#include "ui/files/FileActions.h"

#include "model/bus/BusDrives.h"
#include "ui/files/BackupDialog.h"
#include "ui/files/BackupViewer.h"
#include "ui/files/CompareDialog.h"
#include "ui/files/RestoreDialog.h"

#include <QAction>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QMenu>
#include <QTimer>

namespace opentop {

namespace {

const QString& fileFilter()
{
    static const QString filter = QCoreApplication::translate(
        "opentop::FileActions", "OpenTOP backups (*.json);;All files (*)");
    return filter;
}

} // namespace

FileActions::FileActions(QWidget* window, QMenu* menu, std::function<BusDrives*()> drives,
                         std::function<QVector<int>()> selected,
                         std::function<ConnectionSettings()> connection, QObject* parent)
    : QObject(parent)
    , m_window(window)
    , m_drives(std::move(drives))
    , m_selected(std::move(selected))
    , m_connection(std::move(connection))
{
    m_backupSelected = menu->addAction(tr("&Back up selected drive…"), this, [this] {
        const QVector<int> slaves = m_selected();
        if (!slaves.isEmpty())
            backUp(slaves);
    });
    m_backupSelected->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    m_backupBus = menu->addAction(tr("Back up &whole bus…"), this, [this] {
        const QVector<int> slaves = identifiedDrives();
        if (!slaves.isEmpty())
            backUp(slaves);
    });
    m_backupBus->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B));
    m_backupBus->setToolTip(tr("Save the settings of every identified drive to one file"));
    menu->addSeparator();
    m_open = menu->addAction(tr("&Open backup file…"), this, &FileActions::openFile);
    m_open->setShortcut(QKeySequence::Open);
    m_open->setToolTip(tr("Show the drives and settings a backup file holds"));
    m_compare = menu->addAction(tr("Co&mpare…"), this, &FileActions::compare);
    m_compare->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    m_compare->setToolTip(
        tr("Compare drives and backup files side by side, or against factory defaults"));
    m_restore = menu->addAction(tr("&Restore from file…"), this, &FileActions::restore);
    m_restore->setToolTip(tr("Preview, then write a backup's settings back to drives"));
    // The drives come and go with scans and connections; the menu is always current when shown
    // and the shortcuts within a second.
    connect(menu, &QMenu::aboutToShow, this, &FileActions::updateActions);
    auto* timer = new QTimer(this);
    connect(timer, &QTimer::timeout, this, &FileActions::updateActions);
    timer->start(1000);
    updateActions();
}

QVector<int> FileActions::identifiedDrives() const
{
    QVector<int> slaves;
    BusDrives* drives = m_drives();
    if (drives) {
        for (int slave : drives->slaves()) {
            if (drives->session(slave))
                slaves << slave;
        }
    }
    return slaves;
}

void FileActions::updateActions()
{
    BusDrives* drives = m_drives();
    QVector<int> selected;
    for (int slave : m_selected()) {
        if (drives && drives->session(slave))
            selected << slave;
    }
    const bool any = !identifiedDrives().isEmpty();
    m_backupSelected->setEnabled(!selected.isEmpty());
    m_backupSelected->setText(selected.size() > 1 ? tr("&Back up selected drives…")
                                                  : tr("&Back up selected drive…"));
    m_backupSelected->setToolTip(selected.isEmpty()
                                     ? tr("Select an identified drive in the bus list first")
                                     : tr("Save the settings of the selected drive(s) to a file"));
    m_backupBus->setEnabled(any);
    m_restore->setEnabled(any);
}

void FileActions::backUp(const QVector<int>& slaves)
{
    const QString suggested = QDir::home().filePath(
        QStringLiteral("opentop-%1.json")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmm"))));
    const QString path =
        QFileDialog::getSaveFileName(m_window, tr("Back up to file"), suggested, fileFilter());
    if (path.isEmpty())
        return;
    auto* dialog = new BackupDialog(m_drives(), m_connection(), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    dialog->startBackup(slaves, path);
}

void FileActions::openFile()
{
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Open backup file"), QString(), fileFilter());
    if (path.isEmpty())
        return;
    auto* viewer = new BackupViewer(m_window);
    viewer->setAttribute(Qt::WA_DeleteOnClose);
    viewer->open(path); // a refused file shows why in the viewer
    viewer->show();
}

void FileActions::compare()
{
    auto* dialog = new CompareDialog(m_drives(), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    const QVector<int> selected = m_selected();
    if (!selected.isEmpty())
        dialog->setDriveSide(CompareDialog::A, selected.first());
    dialog->show();
}

void FileActions::restore()
{
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Restore from backup file"),
                                                      QString(), fileFilter());
    if (path.isEmpty())
        return;
    auto* dialog = new RestoreDialog(m_drives(), m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setPath(path);
    dialog->show();
}

} // namespace opentop
