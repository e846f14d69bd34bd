#include "ui/main/LinkBar.h"

#include "ui/widgets/BarHideButton.h"
#include "ui/widgets/PlainText.h"

#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace opentop {

LinkBar::LinkBar(QAction* reconnect, QWidget* parent)
    : QFrame(parent)
    , m_text(new QLabel(this))
    , m_reconnect(new QToolButton(this))
{
    setObjectName(QStringLiteral("linkBar"));
    setFrameShape(QFrame::StyledPanel);
    m_text->setObjectName(QStringLiteral("linkBarText"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::PlainText); // the drives' models, the port's name
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_reconnect->setObjectName(QStringLiteral("linkBarReconnect"));
    m_reconnect->setDefaultAction(reconnect);
    m_reconnect->setToolButtonStyle(Qt::ToolButtonTextOnly);
    auto* close = new BarHideButton(this);
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(8, 4, 4, 4);
    row->addWidget(m_text, 1);
    row->addWidget(m_reconnect);
    row->addWidget(close);
    hide();
}

void LinkBar::say(const QString& text, Look look, const QString& details)
{
    m_look = look;
    m_text->setText(text);
    setToolTip(
        PlainText::asWritten(details.isEmpty() ? text : text + QStringLiteral("\n\n") + details));
    static const char* const colours[] = {"#fdecea", "#eef1f5", "#fff4e5"};
    setStyleSheet(QStringLiteral("#linkBar { background: %1; } #linkBarText { color: black; }")
                      .arg(QLatin1String(colours[int(look)])));
    // Reconnect is what the bar offers while the link is down; after reconnecting it is no news.
    m_reconnect->setVisible(look != Look::Attention);
    show();
}

QString LinkBar::text() const
{
    return m_text->text();
}

} // namespace opentop
