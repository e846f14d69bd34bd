#include "main/WindowGeometry.h"

#include "bus/BusListModel.h"
#include "bus/BusPanel.h"

#include <QGuiApplication>
#include <QHeaderView>
#include <QMainWindow>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <algorithm>

namespace opentop {

WindowGeometry::WindowGeometry(QMainWindow* window, QSplitter* splitter)
    : m_window(window)
    , m_splitter(splitter)
{
}

void WindowGeometry::restore()
{
    QSettings settings;
    fitToScreen(m_window->restoreGeometry(
        settings.value(QStringLiteral("mainWindow/geometry")).toByteArray()));
    m_window->restoreState(settings.value(QStringLiteral("mainWindow/state")).toByteArray());
    m_splitterState = settings.value(QStringLiteral("mainWindow/splitter")).toByteArray();
}

void WindowGeometry::fitToScreen(bool remembered)
{
    // Laptop first: never larger than the screen's available area (a 1366×768 screen has about
    // 730 px for a window once its panel and the title bar are taken), and a remembered geometry
    // from a larger screen is brought back onto this one.
    const QRect available =
        (m_window->screen() ? m_window->screen() : QGuiApplication::primaryScreen())
            ->availableGeometry();
    const QSize frame(8, 32); // the window manager's frame and title bar, before it tells
    const QSize room = available.size() - frame;
    QSize size = remembered ? m_window->size() : QSize(1280, 800);
    size = size.boundedTo(room);
    m_window->resize(size);
    QPoint at = remembered ? m_window->pos() : available.topLeft();
    at.setX(std::max(available.left(),
                     std::min(at.x(), available.right() + 1 - size.width() - frame.width())));
    at.setY(std::max(available.top(),
                     std::min(at.y(), available.bottom() + 1 - size.height() - frame.height())));
    m_window->move(at);
}

void WindowGeometry::divide(BusPanel* panel)
{
    // The remembered division, or one where the bus list shows its first columns up to the
    // control priority (the rest scroll) and the drive's pages keep the most of a laptop's width.
    if (!m_splitter->restoreState(m_splitterState)) {
        const QHeaderView* header = panel->view()->horizontalHeader();
        const int priorityEnd = header->sectionPosition(BusListModel::Priority) +
                                header->sectionSize(BusListModel::Priority);
        const int list =
            std::clamp(priorityEnd + 40, 360, std::max(360, m_window->width() * 2 / 5));
        m_splitter->setSizes({list, std::max(600, m_window->width() - list)});
    }
}

void WindowGeometry::save()
{
    QSettings settings;
    settings.setValue(QStringLiteral("mainWindow/geometry"), m_window->saveGeometry());
    settings.setValue(QStringLiteral("mainWindow/state"), m_window->saveState());
    m_splitterState = m_splitter->saveState();
    settings.setValue(QStringLiteral("mainWindow/splitter"), m_splitterState);
}

} // namespace opentop
