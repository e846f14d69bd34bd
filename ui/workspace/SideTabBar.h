#pragma once

#include <QTabBar>

namespace opentop {

// A tab bar for the side of a page stack (QTabWidget::West) whose titles read across, like a
// list of pages: as many pages as the height holds, none behind scroll arrows, each title whole.
class SideTabBar : public QTabBar
{
    Q_OBJECT
public:
    explicit SideTabBar(QWidget* parent = nullptr);

protected:
    static constexpr int kMargin = 12;
    QSize tabSizeHint(int index) const override;
    QSize minimumTabSizeHint(int index) const override;
    void paintEvent(QPaintEvent* event) override;
};

} // namespace opentop
