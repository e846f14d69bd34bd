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

    // STOP ALL first, then every action of `window` with a shortcut: its menus' actions in
    // menu order, each under its own menu, then actions outside the menus.
    static QVector<Entry> collect(QMainWindow* window);
    QTableWidget* table() const { return m_table; }

private:
    QTableWidget* m_table;
};

} // namespace opentop
