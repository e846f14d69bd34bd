#pragma once

#include <QFrame>

class QAction;
class QLabel;
class QToolButton;

namespace opentop {

// A bar above the drive's pages about the link: while it is lost, what was known of the drives
// when it dropped, what to check on the machine and Reconnect (Ctrl+R); while reconnecting, that
// it is; after reconnecting, the drives that still run or are in communication priority, as
// read again. It never covers anything: it takes a row of the window and can be hidden.
class LinkBar : public QFrame
{
    Q_OBJECT
public:
    enum class Look
    {
        Lost,      // red: the link is down
        Busy,      // neutral: reconnecting
        Attention, // amber: reconnected, a drive needs a look
    };

    // `reconnect`: the Bus menu's Reconnect, which the bar's button follows.
    LinkBar(QAction* reconnect, QWidget* parent = nullptr);

    // Shows `text` (the whole of it in the tooltip with `details`).
    void say(const QString& text, Look look, const QString& details = QString());
    QString text() const;
    Look look() const { return m_look; }
    QToolButton* reconnectButton() const { return m_reconnect; }

private:
    QLabel* m_text;
    QToolButton* m_reconnect;
    Look m_look = Look::Lost;
};

} // namespace opentop
