#pragma once

#include <QToolButton>

namespace opentop {

// The "×" at the end of a bar above the drive's pages (the drives last seen, the link): hides
// the bar it is given, which shows again when it has something new to say.
class BarHideButton : public QToolButton
{
    Q_OBJECT
public:
    explicit BarHideButton(QWidget* bar);
};

} // namespace opentop
