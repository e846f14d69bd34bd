// Finds what a user would see as a broken layout in a shown window: a window larger than the
// screen, a widget reaching out of its parent, two sibling widgets on top of each other, a text
// that does not fit its label, button, tab or column header, tabs behind scroll arrows, a tool
// bar or menu bar whose items spill into an extension menu. Each problem names the widget
// (class, objectName, text) and where it is, so that a failure says what to fix.
#pragma once

#include <QAbstractAxis>
#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDockWidget>
#include <QGraphicsView>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QStyle>
#include <QTabBar>
#include <QTextBoundaryFinder>
#include <QTextEdit>
#include <QToolBar>
#include <QToolButton>

namespace opentop::test {

class LayoutInspector
{
public:
    // The problems of `window` (a top-level widget, shown) on `screen` (available geometry).
    static QStringList problems(QWidget* window, const QRect& screen)
    {
        LayoutInspector inspector;
        const QRect frame = window->frameGeometry();
        if (frame.width() > screen.width() || frame.height() > screen.height()) {
            inspector.add(window, QStringLiteral("window is %1×%2 px, larger than the %3×%4 screen")
                                      .arg(frame.width())
                                      .arg(frame.height())
                                      .arg(screen.width())
                                      .arg(screen.height()));
        }
        inspector.inspect(window, window);
        return inspector.m_problems;
    }

    static QString describe(const QWidget* w)
    {
        QString text = textOf(w);
        if (text.size() > 60)
            text = text.left(57) + QStringLiteral("...");
        QString name = w->objectName();
        if (name.isEmpty()) {
            // The nearest named ancestor says where an unnamed widget is.
            for (const QWidget* p = w->parentWidget(); p; p = p->parentWidget()) {
                if (!p->objectName().isEmpty() &&
                    !p->objectName().startsWith(QLatin1String("qt_"))) {
                    name = QStringLiteral("in %1").arg(p->objectName());
                    break;
                }
            }
        }
        const QPoint at = w->mapTo(w->window(), QPoint(0, 0));
        return QStringLiteral("%1 '%2' \"%3\" at (%4,%5) %6×%7")
            .arg(QString::fromLatin1(w->metaObject()->className()), name, text)
            .arg(at.x())
            .arg(at.y())
            .arg(w->width())
            .arg(w->height());
    }

    // Why `w` is not wholly in sight in its window (scrolled away, cut by a parent), or empty.
    static QString outOfSight(const QWidget* w)
    {
        QRect seen = w->rect();
        for (const QWidget* p = w; p->parentWidget() && !p->isWindow(); p = p->parentWidget()) {
            seen.translate(p->pos());
            seen &= p->parentWidget()->rect();
        }
        const QRect whole(w->mapTo(w->window(), QPoint(0, 0)), w->size());
        // A pixel or two of a widget's own frame or padding under an edge hides nothing.
        if (seen.width() >= whole.width() - 2 && seen.height() >= whole.height() - 2)
            return QString();
        return QStringLiteral("only %1×%2 px of %3×%4 in sight without scrolling")
            .arg(std::max(0, seen.width()))
            .arg(std::max(0, seen.height()))
            .arg(whole.width())
            .arg(whole.height());
    }

    // The cells of `view` whose text is cut (elided) and not explained by a tooltip.
    static QStringList cutCells(const QAbstractItemView* view)
    {
        QStringList cut;
        const QAbstractItemModel* model = view->model();
        if (!model)
            return cut;
        for (int row = 0; row < std::min(model->rowCount(), 100); ++row) {
            for (int column = 0; column < model->columnCount(); ++column) {
                const QModelIndex index = model->index(row, column);
                const QRect r = view->visualRect(index);
                const QString text = index.data(Qt::DisplayRole).toString();
                if (r.isEmpty() || text.isEmpty())
                    continue;
                // The style's text margins (focus frame margin + 1) either side, and a
                // decoration if there is one.
                int needed = view->fontMetrics().horizontalAdvance(text) + 6;
                if (!index.data(Qt::DecorationRole).isNull())
                    needed += view->iconSize().isValid() ? view->iconSize().width() + 4 : 20;
                if (needed > r.width())
                    cut << QStringLiteral("\"%1\" needs %2 px, has %3")
                               .arg(text)
                               .arg(needed)
                               .arg(r.width());
            }
        }
        return cut;
    }

private:
    // A chart whose axis titles do not fit along its plot area is drawn with "S…" and "…".
    void checkChart(const QChartView* view)
    {
        const QChart* chart = view->chart();
        if (!chart || !view->isVisible())
            return;
        const QRectF plot = chart->plotArea();
        for (const QAbstractAxis* axis : chart->axes()) {
            if (!axis->isVisible() || axis->titleText().isEmpty())
                continue;
            const bool vertical = axis->orientation() == Qt::Vertical;
            const int room = int(vertical ? plot.height() : plot.width());
            const int needed = QFontMetrics(axis->titleFont()).horizontalAdvance(axis->titleText());
            if (needed > room)
                add(view, QStringLiteral("axis title \"%1\" needs %2 px, the plot has %3")
                              .arg(axis->titleText())
                              .arg(needed)
                              .arg(room));
        }
    }

    static QString plain(QString text)
    {
        text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
        return text;
    }

    static QString textOf(const QWidget* w)
    {
        if (const auto* l = qobject_cast<const QLabel*>(w))
            return l->text();
        if (const auto* b = qobject_cast<const QAbstractButton*>(w))
            return plain(b->text());
        if (const auto* d = qobject_cast<const QDockWidget*>(w))
            return d->windowTitle();
        return QString();
    }

    void add(const QWidget* w, const QString& what)
    {
        const QString line = describe(w) + QStringLiteral(": ") + what;
        if (!m_problems.contains(line))
            m_problems << line;
    }

    // Widgets whose children are their own business (the parts of a combo box, a spin box, a
    // chart): looked at as a whole, not inside.
    static bool isOpaque(const QWidget* w)
    {
        return qobject_cast<const QAbstractSpinBox*>(w) || qobject_cast<const QComboBox*>(w) ||
               qobject_cast<const QLineEdit*>(w) || qobject_cast<const QGraphicsView*>(w) ||
               qobject_cast<const QTextEdit*>(w) || qobject_cast<const QTabBar*>(w) ||
               qobject_cast<const QMenuBar*>(w) || qobject_cast<const QAbstractButton*>(w) ||
               (qobject_cast<const QAbstractScrollArea*>(w) &&
                !qobject_cast<const QScrollArea*>(w));
    }

    static QList<QWidget*> visibleChildren(QWidget* w)
    {
        QList<QWidget*> children;
        for (QObject* o : w->children()) {
            auto* c = qobject_cast<QWidget*>(o);
            // A main window parks the docks of a tab group that are not in front (and its
            // unused tab bars) outside itself: out of sight, not out of place.
            const bool parked =
                qobject_cast<QMainWindow*>(w) && c && !w->rect().intersects(c->geometry());
            if (c && !c->isWindow() && c->isVisible() && !parked)
                children << c;
        }
        return children;
    }

    void inspect(QWidget* w, QWidget* window)
    {
        checkText(w);
        if (auto* bar = qobject_cast<QTabBar*>(w))
            checkTabs(bar);
        if (auto* chart = qobject_cast<QChartView*>(w))
            checkChart(chart);
        if (auto* table = qobject_cast<QAbstractItemView*>(w)) {
            for (QHeaderView* h :
                 table->findChildren<QHeaderView*>(QString(), Qt::FindDirectChildrenOnly))
                checkHeader(h, table);
        }
        if (qobject_cast<QToolBar*>(w) || qobject_cast<QMenuBar*>(w)) {
            for (QToolButton* b : w->findChildren<QToolButton*>()) {
                if (b->objectName().endsWith(QLatin1String("_ext_button")) && b->isVisible())
                    add(w, QStringLiteral("items do not fit: some are behind the » button"));
            }
        }
        if (isOpaque(w))
            return;
        const QList<QWidget*> children = visibleChildren(w);
        // A scroll area's contents may be larger than its viewport: that is what it is for.
        const bool scrolled = qobject_cast<QScrollArea*>(w->parentWidget()) &&
                              w->objectName() == QLatin1String("qt_scrollarea_viewport");
        for (QWidget* c : children) {
            const QRect g = c->geometry();
            if (!scrolled && !w->rect().adjusted(-1, -1, 1, 1).contains(g)) {
                add(c, QStringLiteral("reaches out of its parent %1 (%2×%3)")
                           .arg(QString::fromLatin1(w->metaObject()->className()))
                           .arg(w->width())
                           .arg(w->height()));
            }
        }
        if (!qobject_cast<QStackedWidget*>(w)) {
            for (int i = 0; i < children.size(); ++i) {
                for (int j = i + 1; j < children.size(); ++j) {
                    const QRect both = children[i]->geometry() & children[j]->geometry();
                    if (both.width() > 2 && both.height() > 2 &&
                        !mayOverlap(children[i], children[j]))
                        add(children[i], QStringLiteral("overlaps %1").arg(describe(children[j])));
                }
            }
        }
        for (QWidget* c : children)
            inspect(c, window);
    }

    static bool mayOverlap(const QWidget* a, const QWidget* b)
    {
        // The size grip sits in the status bar's corner on purpose; a QMainWindow's separator
        // handles and a rubber band are drawn over the others.
        for (const QWidget* w : {a, b}) {
            if (w->inherits("QSizeGrip") || w->inherits("QRubberBand") ||
                w->inherits("QFocusFrame"))
                return true;
        }
        return false;
    }

    void checkText(QWidget* w)
    {
        if (auto* label = qobject_cast<QLabel*>(w)) {
            const QString text = label->text();
            if (text.isEmpty() || label->pixmap().cacheKey() != 0)
                return;
            // Shortened on purpose, with the whole text in the tooltip.
            if (text.contains(QChar(0x2026)) && !label->toolTip().isEmpty())
                return;
            const QRect room = label->contentsRect();
            if (label->wordWrap()) {
                const int needed = label->heightForWidth(label->width());
                if (needed > label->height() + 1)
                    add(w, QStringLiteral("wrapped text needs %1 px high, has %2")
                               .arg(needed)
                               .arg(label->height()));
                const int word = longestWord(label);
                if (word > room.width() + 1)
                    add(w,
                        QStringLiteral("a word needs %1 px, has %2").arg(word).arg(room.width()));
                return;
            }
            const QSize needed = label->minimumSizeHint();
            if (needed.width() > label->width() + 1)
                add(w, QStringLiteral("text needs %1 px wide, has %2")
                           .arg(needed.width())
                           .arg(label->width()));
            else if (needed.height() > label->height() + 1)
                add(w, QStringLiteral("text needs %1 px high, has %2")
                           .arg(needed.height())
                           .arg(label->height()));
            return;
        }
        if (auto* button = qobject_cast<QAbstractButton*>(w)) {
            const QString text = plain(button->text());
            if (text.isEmpty() || w->parentWidget()->inherits("QTabBar"))
                return;
            if (qobject_cast<QPushButton*>(w) || qobject_cast<QToolButton*>(w)) {
                int needed = w->fontMetrics().horizontalAdvance(text) + 8;
                if (!button->icon().isNull())
                    needed += button->iconSize().width() + 4;
                if (needed > button->width())
                    add(w, QStringLiteral("text needs %1 px wide, has %2")
                               .arg(needed)
                               .arg(button->width()));
            } else if (button->sizeHint().width() > button->width() + 1) {
                add(w, QStringLiteral("text needs %1 px wide, has %2")
                           .arg(button->sizeHint().width())
                           .arg(button->width()));
            }
            if (w->fontMetrics().height() > button->height())
                add(w, QStringLiteral("text needs %1 px high, has %2")
                           .arg(w->fontMetrics().height())
                           .arg(button->height()));
        }
    }

    static int longestWord(const QLabel* label)
    {
        if (label->textFormat() == Qt::RichText || Qt::mightBeRichText(label->text()))
            return 0;
        // The longest piece the text may not be broken in: between spaces in English, but
        // between any two ideographs in Chinese or Japanese (Unicode line breaking, as Qt wraps).
        const QString text = label->text();
        QTextBoundaryFinder lines(QTextBoundaryFinder::Line, text);
        int longest = 0;
        int start = 0;
        while (lines.toNextBoundary() != -1) {
            const int end = int(lines.position());
            longest = std::max(longest, label->fontMetrics().horizontalAdvance(
                                            text.mid(start, end - start).trimmed()));
            start = end;
        }
        return longest;
    }

    void checkTabs(QTabBar* bar)
    {
        for (QToolButton* b : bar->findChildren<QToolButton*>()) {
            if (b->isVisible()) {
                add(bar, QStringLiteral("tabs hidden behind scroll arrows"));
                break;
            }
        }
        const bool vertical =
            bar->shape() == QTabBar::RoundedWest || bar->shape() == QTabBar::RoundedEast ||
            bar->shape() == QTabBar::TriangularWest || bar->shape() == QTabBar::TriangularEast;
        for (int i = 0; i < bar->count(); ++i) {
            if (!bar->isTabVisible(i))
                continue;
            const QString text = plain(bar->tabText(i));
            const QRect r = bar->tabRect(i);
            const int room = vertical ? std::max(r.width(), r.height()) : r.width();
            // The style's padding either side, as a tab's own size hint has it.
            const int needed = bar->fontMetrics().horizontalAdvance(text) +
                               bar->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, bar);
            if (!bar->rect().contains(r))
                add(bar, QStringLiteral("tab \"%1\" is outside the tab bar").arg(text));
            else if (needed > room)
                add(bar, QStringLiteral("tab \"%1\" needs %2 px, has %3")
                             .arg(text)
                             .arg(needed)
                             .arg(room));
        }
    }

    void checkHeader(QHeaderView* header, QAbstractItemView* view)
    {
        if (!header || !header->isVisible() || !view->model() ||
            header->orientation() != Qt::Horizontal)
            return;
        const int margin = header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
        for (int section = 0; section < header->count(); ++section) {
            if (header->isSectionHidden(section))
                continue;
            const QString text =
                view->model()->headerData(section, Qt::Horizontal, Qt::DisplayRole).toString();
            const int size = header->sectionSize(section);
            const int at = header->sectionViewportPosition(section);
            // A column a scroll bar reaches is in reach; one beyond the edge without it is lost.
            const bool reachable = view->horizontalScrollBar()->isVisible();
            if (!reachable && (at + size > header->viewport()->width() + 1 || at < 0)) {
                add(view, QStringLiteral("column \"%1\" is out of sight (at %2 px, %3 px wide; "
                                         "%4 px shown)")
                              .arg(text)
                              .arg(at)
                              .arg(size)
                              .arg(header->viewport()->width()));
                continue;
            }
            if (text.isEmpty())
                continue;
            QFont font = header->font();
            const int needed = QFontMetrics(font).horizontalAdvance(text) + 2 * margin;
            const bool explained =
                !view->model()->headerData(section, Qt::Horizontal, Qt::ToolTipRole).isNull();
            if (needed > size && !explained)
                add(view, QStringLiteral("column header \"%1\" needs %2 px, has %3")
                              .arg(text)
                              .arg(needed)
                              .arg(size));
        }
    }

    QStringList m_problems;
};

} // namespace opentop::test
