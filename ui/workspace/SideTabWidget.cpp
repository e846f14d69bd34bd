#include "workspace/SideTabWidget.h"

#include "workspace/SideTabBar.h"

namespace opentop {

SideTabWidget::SideTabWidget(QWidget* parent)
    : QTabWidget(parent)
{
    setTabBar(new SideTabBar(this));
    setTabPosition(QTabWidget::West);
    setDocumentMode(false);
}

} // namespace opentop
