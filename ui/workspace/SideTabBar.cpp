#include "workspace/SideTabBar.h"

#include <QStyleOptionTab>
#include <QStylePainter>
#include <algorithm>

namespace opentop {

SideTabBar::SideTabBar(QWidget* parent)
    : QTabBar(parent)
{
    setUsesScrollButtons(false);
    setElideMode(Qt::ElideNone);
    setExpanding(false);
}

QSize SideTabBar::tabSizeHint(int index) const
{
    // The style sizes a side tab for text running down it: turned, it holds the text across.
    QSize size = QTabBar::tabSizeHint(index);
    size.transpose();
    // As high as a line of a list: ten pages in the height of a laptop's window.
    size.setHeight(std::min(size.height(), fontMetrics().height() + 12));
    return size;
}

QSize SideTabBar::minimumTabSizeHint(int index) const
{
    return tabSizeHint(index);
}

void SideTabBar::paintEvent(QPaintEvent* /*event*/)
{
    QStylePainter painter(this);
    QStyleOptionTab option;
    for (int i = 0; i < count(); ++i) {
        initStyleOption(&option, i);
        painter.drawControl(QStyle::CE_TabBarTabShape, option);
        // The label drawn as on a top tab (text across), in the same rectangle.
        option.shape = QTabBar::RoundedNorth;
        option.rect = tabRect(i).adjusted(6, 0, -6, 0);
        painter.drawControl(QStyle::CE_TabBarTabLabel, option);
    }
}

} // namespace opentop
