#include "ui/main/WindowGeometry.h"

#include "ui/bus/BusListModel.h"
#include "ui/bus/BusPanel.h"

#include <QEvent>
#include <QGuiApplication>
#include <QHeaderView>
#include <QLayout>
#include <QMainWindow>
#include <QScreen>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <algorithm>
#include <functional>

namespace opentop {

namespace {

// Calls back when `watched` is resized; lives as long as `owner`.
class OnResize : public QObject
{
public:
    OnResize(QWidget* watched, QObject* owner, std::function<void()> callback)
        : QObject(owner)
        , m_callback(std::move(callback))
    {
        watched->installEventFilter(this);
    }

    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == QEvent::Resize)
            m_callback();
        return false;
    }

private:
    std::function<void()> m_callback;
};

} // namespace

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
    // The remembered division, or one where the bus list shows every column whole (which
    // drive, what it is, its state, who controls it, its switches and firmware) while the
    // drive's pages keep what they need on a laptop. Divided again as drives
    // are listed, until the user moves the divider.
    if (m_splitter->restoreState(m_splitterState))
        return;
    const auto fit = [this, panel] {
        if (m_userDivided)
            return;
        // The pages keep what they need, and never less than 800 px (their tabs take 200).
        const int pages = std::max(800, m_splitter->widget(1)->minimumSizeHint().width());
        const int list =
            std::clamp(wholeWidth(panel), 360, std::max(360, m_window->width() - pages));
        if (m_splitter->sizes().value(0) == list)
            return; // polled states change the data often; the division rarely
        m_splitter->setSizes({list, std::max(600, m_window->width() - list)});
    };
    fit();
    QObject::connect(m_splitter, &QSplitter::splitterMoved, m_splitter,
                     [this] { m_userDivided = true; });
    QAbstractItemModel* model = panel->view()->model();
    for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
        QObject::connect(model, signal, panel, fit);
    QObject::connect(model, &QAbstractItemModel::dataChanged, panel, fit);
    new OnResize(m_splitter, panel, fit); // a maximised or restored window divides again
}

int WindowGeometry::wholeWidth(BusPanel* panel)
{
    // QAbstractItemView's public sizeHintForColumn (QTableView makes its override protected).
    const QAbstractItemView* view = panel->view();
    const QHeaderView* header = panel->view()->horizontalHeader();
    int width = 0;
    for (int c = 0; c < header->count(); ++c) {
        if (!header->isSectionHidden(c))
            width += std::max(view->sizeHintForColumn(c), header->sectionSizeHint(c));
    }
    const QMargins margins = panel->layout() ? panel->layout()->contentsMargins() : QMargins();
    return width + 2 * panel->view()->frameWidth() +
           panel->view()->verticalScrollBar()->sizeHint().width() + margins.left() +
           margins.right();
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
