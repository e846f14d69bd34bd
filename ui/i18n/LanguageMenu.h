#pragma once

#include <QMenu>

class QActionGroup;

namespace opentop {

// View ▸ Language: the system's language or one chosen, saved for the next start (translators
// are installed before any window exists, so a change needs a restart, which the user is told).
class LanguageMenu : public QMenu
{
    Q_OBJECT
public:
    explicit LanguageMenu(QWidget* parent = nullptr);

    // The saved choice ("" = the system's) after the user picked `code`.
    void choose(const QString& code);

signals:
    // The choice differs from the language running now: the window says a restart applies it.
    void restartNeeded(const QString& code);

private:
    QActionGroup* m_group = nullptr;
};

} // namespace opentop
