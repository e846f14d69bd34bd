#pragma once

#include <QObject>
#include <QVector>

class QMenu;
class QWidget;

namespace opentop {

class BusDrives;
class BusPanel;

// The bus list's context menu for the drives selected: their variant (VariantMenu, where the
// bus does not tell it), the machine's name (one drive), identify again, the line format, remove
// from the list. Naming asks again, with the model's reason, until the name is taken or the user
// cancels.
class BusListMenu : public QObject
{
    Q_OBJECT
public:
    BusListMenu(BusPanel* panel, BusDrives* drives);

    // The menu for `slaves` (the caller owns it).
    QMenu* menuFor(const QVector<int>& slaves, QWidget* parent);
    // Asks the name of the machine at `slave` (modal) and gives it to BusDrives.
    void askName(int slave);

signals:
    // What happened, for the panel's message line ("Machine number 1 is now named …").
    void message(const QString& text);

private:
    BusPanel* m_panel;
    BusDrives* m_drives;
};

} // namespace opentop
