#include "ui/i18n/LanguageMenu.h"

#include "model/i18n/Language.h"

#include <QActionGroup>

namespace opentop {

LanguageMenu::LanguageMenu(QWidget* parent)
    : QMenu(tr("&Language"), parent)
    , m_group(new QActionGroup(this))
{
    setObjectName(QStringLiteral("languageMenu"));
    const QString saved = Language::saved();
    QAction* system =
        addAction(tr("System language (%1)")
                      .arg(Language::nativeName(Language::forLocale(QLocale::system()))));
    system->setData(QString());
    system->setCheckable(true);
    system->setChecked(saved.isEmpty());
    m_group->addAction(system);
    addSeparator();
    // Native names without accelerators: they are written in their own scripts.
    for (const QString& code : Language::available()) {
        QAction* a = addAction(Language::nativeName(code));
        a->setData(code);
        a->setCheckable(true);
        a->setChecked(saved == code);
        m_group->addAction(a);
    }
    connect(m_group, &QActionGroup::triggered, this,
            [this](QAction* a) { choose(a->data().toString()); });
}

void LanguageMenu::choose(const QString& code)
{
    Language::save(code);
    for (QAction* a : m_group->actions())
        a->setChecked(a->data().toString() == code);
    const QString next = code.isEmpty() ? Language::forLocale(QLocale::system()) : code;
    if (next != Language::current())
        emit restartNeeded(next);
}

} // namespace opentop
