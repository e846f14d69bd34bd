#include "ui/workspace/SideTabBar.h"

#include <QStyleOptionTab>
#include <QStylePainter>

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
    // A line of a list: the title across with a margin each side, and as high as a line (ten
    // pages in the height of a laptop's window).
    QFont bold = font(); // the current page's title is bold
    bold.setBold(true);
    const QFontMetrics metrics(bold);
    return QSize(metrics.horizontalAdvance(tabText(index)) + 2 * kMargin, metrics.height() + 12);
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
        // The title across, from the left, as in a list.
        const QRect text = tabRect(i).adjusted(kMargin, 0, -kMargin / 2, 0);
        QFont font = painter.font();
        font.setBold(i == currentIndex());
        painter.setFont(font);
        style()->drawItemText(&painter, text, Qt::AlignLeft | Qt::AlignVCenter, option.palette,
                              isTabEnabled(i), tabText(i), QPalette::WindowText);
    }
}

} // namespace opentop
