#include "ui/help/ShortcutsDialog.h"

#include "ui/run/StopAllButton.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>
#include <functional>

namespace opentop {

namespace {

// "&Scan bus…" as read: "Scan bus".
QString plain(QString text)
{
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    text.replace(QStringLiteral("&&"), QStringLiteral("&"));
    text.remove(QChar(0x2026));
    text.remove(QStringLiteral("..."));
    return text.trimmed();
}

} // namespace

QVector<ShortcutsDialog::Entry> ShortcutsDialog::collect(QMainWindow* window)
{
    // STOP ALL first: the one to find at once.
    QVector<Entry> entries{{tr("Everywhere, dialogs included"),
                            tr("STOP ALL (stop every drive on the bus)"),
                            StopAllButton::shortcuts()}};
    QList<QAction*> listed;
    const std::function<void(QMenu*, const QString&)> addMenu = [&](QMenu* menu,
                                                                    const QString& where) {
        for (QAction* a : menu->actions()) {
            if (a->menu()) {
                addMenu(a->menu(), where + QStringLiteral(" ▸ ") + plain(a->text()));
                continue;
            }
            if (a->isSeparator() || a->shortcuts().isEmpty() || listed.contains(a))
                continue;
            listed << a;
            entries.append({where, plain(a->text()), a->shortcuts()});
        }
    };
    if (window->menuBar()) {
        for (QAction* a : window->menuBar()->actions()) {
            if (a->menu())
                addMenu(a->menu(), plain(a->text()));
        }
    }
    for (QAction* a : window->findChildren<QAction*>()) {
        if (a->shortcuts().isEmpty() || listed.contains(a) || a->text().isEmpty())
            continue;
        listed << a;
        entries.append({tr("Main window"), plain(a->text()), a->shortcuts()});
    }
    return entries;
}

ShortcutsDialog::ShortcutsDialog(QMainWindow* window, QWidget* parent)
    : QDialog(parent)
    , m_table(new QTableWidget(this))
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard shortcuts"));
    const QVector<Entry> entries = collect(window);
    m_table->setObjectName(QStringLiteral("shortcutsTable"));
    m_table->setColumnCount(3);
    m_table->setHorizontalHeaderLabels({tr("Where"), tr("Command"), tr("Keys")});
    m_table->setRowCount(int(entries.size()));
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    for (int row = 0; row < entries.size(); ++row) {
        QStringList keys;
        for (const QKeySequence& k : entries[row].keys)
            keys << k.toString(QKeySequence::NativeText);
        const QStringList texts = {entries[row].where, entries[row].what, keys.join(tr(" or "))};
        for (int column = 0; column < 3; ++column) {
            auto* item = new QTableWidgetItem(texts[column]);
            item->setToolTip(texts[column]);
            m_table->setItem(row, column, item);
        }
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto* note = new QLabel(tr("STOP ALL's keys work in every window of the program, also while a "
                               "dialog is open."),
                            this);
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_table, 1);
    layout->addWidget(note);
    layout->addWidget(buttons);
    const int width = m_table->horizontalHeader()->length() + 40;
    resize(std::min(std::max(width, 480), 900), 520);
}

} // namespace opentop
