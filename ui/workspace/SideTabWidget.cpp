#include "ui/workspace/SideTabWidget.h"

#include "ui/workspace/SideTabBar.h"

#include <QEvent>
#include <QStackedWidget>
#include <QStyle>
#include <QStyleOptionTabWidgetFrame>

namespace opentop {

SideTabWidget::SideTabWidget(QWidget* parent)
    : QTabWidget(parent)
    , m_stack(findChild<QStackedWidget*>(QStringLiteral("qt_tabwidget_stackedwidget"),
                                         Qt::FindDirectChildrenOnly))
{
    setTabBar(new SideTabBar(this));
    setTabPosition(QTabWidget::West);
    setDocumentMode(false);
}

bool SideTabWidget::event(QEvent* event)
{
    // QTabWidget answers every layout request by placing its bar and page stack again and
    // repainting itself whole, page included. A live page asks for one whenever a label's
    // text changes (a value's age: several times a second), which rarely moves the bar or
    // the pages: then the window's layout is told of the page's sizes, and nothing repaints.
    if (event->type() == QEvent::LayoutRequest && isVisible() && m_stack) {
        QStyleOptionTabWidgetFrame option;
        initStyleOption(&option);
        const QRect bar = style()->subElementRect(QStyle::SE_TabWidgetTabBar, &option, this);
        const QRect pages = style()->subElementRect(QStyle::SE_TabWidgetTabContents, &option, this);
        if (tabBar()->geometry() == bar && m_stack->geometry() == pages) {
            updateGeometry();
            return true;
        }
    }
    return QTabWidget::event(event);
}

} // namespace opentop
