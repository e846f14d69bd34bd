#include "ui/run/StopAllKeys.h"

#include "ui/run/StopAllButton.h"

#include <QCoreApplication>
#include <QKeyEvent>

namespace opentop {

StopAllKeys::StopAllKeys(std::function<StopAllButton*()> button, QObject* owner)
    : QObject(owner)
    , m_button(std::move(button))
{
    QCoreApplication::instance()->installEventFilter(this);
}

StopAllKeys::~StopAllKeys()
{
    if (QCoreApplication::instance())
        QCoreApplication::instance()->removeEventFilter(this);
}

bool StopAllKeys::matches(const QKeyEvent* event)
{
    const QKeyCombination pressed(event->modifiers() & ~Qt::KeypadModifier, Qt::Key(event->key()));
    for (const QKeySequence& keys : StopAllButton::shortcuts()) {
        if (keys.count() == 1 && keys[0] == pressed)
            return true;
    }
    return false;
}

bool StopAllKeys::eventFilter(QObject* watched, QEvent* event)
{
    const QEvent::Type type = event->type();
    if (type != QEvent::KeyPress && type != QEvent::ShortcutOverride)
        return QObject::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    if (!matches(key))
        return false;
    if (type == QEvent::ShortcutOverride) {
        // Claim the keys so that no other shortcut takes them; the press comes next.
        event->accept();
        return true;
    }
    // Held keys repeat: one stop per press is enough (each press broadcasts again).
    StopAllButton* button = m_button ? m_button() : nullptr;
    if (button && !key->isAutoRepeat())
        button->stopAll();
    return true;
}

} // namespace opentop
