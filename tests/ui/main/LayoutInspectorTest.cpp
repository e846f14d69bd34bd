// The layout test's inspector finds what it is meant to find (so that a clean report means
// something): overlapping siblings, cut text, tabs behind scroll arrows, a window larger than
// the screen, a column out of reach.
#include "tests/ui/main/LayoutInspector.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <gtest/gtest.h>

using namespace opentop::test;

namespace {

bool mentions(const QStringList& problems, const QString& what, const QString& text)
{
    for (const QString& p : problems) {
        if (p.contains(what) && p.contains(text))
            return true;
    }
    return false;
}

} // namespace

TEST(LayoutInspectorTest, FindsOverlapsCutTextsHiddenTabsAndAWindowLargerThanTheScreen)
{
    QWidget window;
    window.setGeometry(0, 0, 600, 400);
    auto* a = new QLabel(QStringLiteral("first"), &window);
    a->setObjectName(QStringLiteral("first"));
    a->setGeometry(10, 10, 100, 20);
    auto* b = new QLabel(QStringLiteral("second"), &window);
    b->setObjectName(QStringLiteral("second"));
    b->setGeometry(50, 15, 100, 20);
    auto* cut = new QLabel(QStringLiteral("A text much longer than its label"), &window);
    cut->setObjectName(QStringLiteral("cut"));
    cut->setGeometry(10, 60, 40, 20);
    auto* button = new QPushButton(QStringLiteral("Write all pending"), &window);
    button->setObjectName(QStringLiteral("narrowButton"));
    button->setGeometry(10, 90, 30, 28);
    auto* tabs = new QTabWidget(&window);
    tabs->setGeometry(10, 130, 200, 100);
    for (int i = 0; i < 8; ++i)
        tabs->addTab(new QWidget, QStringLiteral("Page number %1").arg(i));
    auto* table = new QTableWidget(2, 6, &window);
    table->setObjectName(QStringLiteral("narrowTable"));
    table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table->setHorizontalHeaderLabels({QStringLiteral("One"), QStringLiteral("Two"),
                                      QStringLiteral("Three"), QStringLiteral("Four"),
                                      QStringLiteral("Five"), QStringLiteral("Control priority")});
    table->setGeometry(250, 130, 300, 100);
    window.show();
    QTest::qWait(50);

    QStringList problems = LayoutInspector::problems(&window, QRect(0, 0, 1366, 768));
    const QString all = problems.join(QLatin1Char('\n'));
    EXPECT_TRUE(
        mentions(problems, QStringLiteral("'first'"), QStringLiteral("overlaps QLabel 'second'")))
        << qPrintable(all);
    EXPECT_TRUE(mentions(problems, QStringLiteral("'cut'"), QStringLiteral("text needs")))
        << qPrintable(all);
    EXPECT_TRUE(mentions(problems, QStringLiteral("'narrowButton'"), QStringLiteral("text needs")))
        << qPrintable(all);
    EXPECT_TRUE(mentions(problems, QStringLiteral("QTabBar"), QStringLiteral("scroll arrows")))
        << qPrintable(all);
    EXPECT_TRUE(mentions(problems, QStringLiteral("'narrowTable'"),
                         QStringLiteral("column \"Control priority\" is out of sight")))
        << qPrintable(all);
    // Nothing said of what is fine.
    EXPECT_FALSE(all.contains(QStringLiteral("window is"))) << qPrintable(all);

    // A window larger than the screen.
    problems = LayoutInspector::problems(&window, QRect(0, 0, 500, 300));
    EXPECT_TRUE(mentions(problems, QStringLiteral("QWidget"),
                         QStringLiteral("larger than the 500×300 screen")))
        << qPrintable(problems.join(QLatin1Char('\n')));
}
