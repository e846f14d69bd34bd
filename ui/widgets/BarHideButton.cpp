#include "ui/widgets/BarHideButton.h"

namespace opentop {

BarHideButton::BarHideButton(QWidget* bar)
    : QToolButton(bar)
{
    setText(QStringLiteral("×"));
    setToolTip(tr("Hide this bar"));
    setAccessibleName(tr("Hide"));
    connect(this, &QToolButton::clicked, bar, &QWidget::hide);
}

} // namespace opentop
