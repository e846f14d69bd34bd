// How the trend lines are cut into the straight pieces TrendCanvas draws: a dash pattern runs
// on across a line's points, as a stroked path has it.
#include "ui/trends/TrendCanvas.h"

#include <QPen>
#include <gtest/gtest.h>

using namespace opentop;

TEST(TrendCanvasTest, ASolidLineIsItsSegments)
{
    const QVector<QLineF> pieces =
        TrendCanvas::pieces({QPointF(0, 0), QPointF(5, 1), QPointF(9, 1)}, QPen(Qt::red, 2));
    ASSERT_EQ(pieces.size(), 2);
    EXPECT_EQ(pieces[0], QLineF(0, 0, 5, 1));
    EXPECT_EQ(pieces[1], QLineF(5, 1, 9, 1));
    EXPECT_TRUE(TrendCanvas::pieces({QPointF(0, 0)}, QPen(Qt::red, 2)).isEmpty());
}

TEST(TrendCanvasTest, ADashRunsOnAcrossThePointsOfTheLine)
{
    // Dashes of 4 and gaps of 2 pen widths: 8 px on, 4 px off at width 2.
    QPen pen(Qt::red, 2);
    pen.setStyle(Qt::DashLine);
    const QVector<QLineF> pieces =
        TrendCanvas::pieces({QPointF(0, 0), QPointF(5, 0), QPointF(30, 0)}, pen);
    // The first dash goes on past the point at 5; the pattern does not start again there.
    const QVector<QLineF> expected{QLineF(0, 0, 5, 0), QLineF(5, 0, 8, 0), QLineF(12, 0, 20, 0),
                                   QLineF(24, 0, 30, 0)};
    ASSERT_EQ(pieces.size(), expected.size());
    for (int i = 0; i < pieces.size(); ++i) {
        EXPECT_NEAR(pieces[i].x1(), expected[i].x1(), 1e-9) << i;
        EXPECT_NEAR(pieces[i].x2(), expected[i].x2(), 1e-9) << i;
    }
}
