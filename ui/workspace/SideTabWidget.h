#pragma once

#include <QTabWidget>

class QStackedWidget;

namespace opentop {

// A page stack with its titles listed on the left (SideTabBar): a drive's ten pages all in
// sight on a laptop's screen, where a row of tabs would hide some behind scroll arrows.
class SideTabWidget : public QTabWidget
{
    Q_OBJECT
public:
    explicit SideTabWidget(QWidget* parent = nullptr);

protected:
    bool event(QEvent* event) override;

private:
    QStackedWidget* m_stack;
};

} // namespace opentop
