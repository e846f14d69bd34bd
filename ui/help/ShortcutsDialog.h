#pragma once

#include <QDialog>
#include <QKeySequence>
#include <QVector>

class QMainWindow;
class QTableWidget;

namespace opentop {

// Help ▸ Keyboard shortcuts: every shortcut of the program, read from the window's actions (so
// that the list cannot drift from what the keys do), and STOP ALL's keys.
class ShortcutsDialog : public QDialog
{
    Q_OBJECT
public:
    struct Entry
    {
        QString where; // the menu ("Bus"), or where else the keys work
        QString what;  // the command, as the menu names it ("Scan bus")
        QList<QKeySequence> keys;
    };
    explicit ShortcutsDialog(QMainWindow* window, QWidget* parent = nullptr);

    // Every action of `window` with a shortcut: its menu's actions first, in menu order, then
    // actions outside the menus, then STOP ALL.
    static QVector<Entry> collect(QMainWindow* window);
    QTableWidget* table() const { return m_table; }

private:
    QTableWidget* m_table;
};

} // namespace opentop
