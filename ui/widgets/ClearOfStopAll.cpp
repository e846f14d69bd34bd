#include "ui/widgets/ClearOfStopAll.h"

#include <QEvent>
#include <QGuiApplication>
#include <QScreen>
#include <QWidget>

namespace opentop {

namespace {

constexpr int kGap = 8; // room between STOP ALL and the window, for the finger and the eye

QRect clampInto(QRect frame, const QRect& region)
{
    frame.moveLeft(
        std::max(region.left(), std::min(frame.left(), region.right() + 1 - frame.width())));
    frame.moveTop(
        std::max(region.top(), std::min(frame.top(), region.bottom() + 1 - frame.height())));
    return frame;
}

} // namespace

void ClearOfStopAll::keep(QWidget* window)
{
    window->installEventFilter(new ClearOfStopAll(window));
}

bool ClearOfStopAll::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Show && watched->isWidgetType())
        place(static_cast<QWidget*>(watched));
    return false;
}

bool ClearOfStopAll::place(QWidget* window)
{
    QWidget* main = window->parentWidget() ? window->parentWidget()->window() : nullptr;
    const QWidget* stop = main ? main->findChild<QWidget*>(QStringLiteral("stopAll")) : nullptr;
    if (!stop || !stop->isVisible())
        return false;
    const QRect button =
        QRect(stop->mapToGlobal(QPoint(0, 0)), stop->size()).adjusted(-kGap, -kGap, kGap, kGap);
    QRect frame = window->frameGeometry();
    if (!frame.intersects(button))
        return false;
    QScreen* screen = main->screen() ? main->screen() : QGuiApplication::primaryScreen();
    const QRect available = screen->availableGeometry();
    const QRect regions[] = {
        QRect(QPoint(available.left(), button.bottom() + 1), available.bottomRight()),
        QRect(available.topLeft(), QPoint(available.right(), button.top() - 1)),
        QRect(QPoint(button.right() + 1, available.top()), available.bottomRight()),
        QRect(available.topLeft(), QPoint(button.left() - 1, available.bottom()))};
    for (const QRect& region : regions) {
        if (region.width() >= frame.width() && region.height() >= frame.height()) {
            window->move(clampInto(frame, region).topLeft());
            return true;
        }
    }
    // Fits nowhere whole: the largest side that holds its minimum size, the window shrunk to it.
    const QSize decoration = frame.size() - window->size();
    const QSize least = window->minimumSizeHint().expandedTo(window->minimumSize()) + decoration;
    const QRect* best = nullptr;
    for (const QRect& region : regions) {
        if (region.width() >= least.width() && region.height() >= least.height() &&
            (!best ||
             qint64(region.width()) * region.height() > qint64(best->width()) * best->height()))
            best = &region;
    }
    if (!best)
        return false;
    frame.setSize(frame.size().boundedTo(best->size()));
    window->resize(frame.size() - decoration);
    window->move(clampInto(frame, *best).topLeft());
    return true;
}

} // namespace opentop
