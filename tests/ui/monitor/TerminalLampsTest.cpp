// The terminal lamps wrap onto more rows where the width does not hold them side by side, and
// never overlap (issue 10 item 13: lamps overlapped unreadably on a laptop).
#include "ui/monitor/TerminalLamps.h"
#include "model/profile/Profile.h"
#include "model/profile/ProfileRegistry.h"

#include <QLabel>
#include <QTest>
#include <QVBoxLayout>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// No two lamps' cells overlap, and every label has the height of its text.
QString problems(const TerminalLamps& lamps)
{
    QStringList found;
    const QList<QLabel*> labels = lamps.findChildren<QLabel*>();
    for (QLabel* l : labels) {
        if (!l->text().isEmpty() && l->height() < l->fontMetrics().height())
            found << QStringLiteral("%1 is %2 px high").arg(l->text()).arg(l->height());
    }
    for (QLabel* a : labels) {
        for (QLabel* b : labels) {
            const QRect ra(a->mapTo(&lamps, QPoint()), a->size());
            const QRect rb(b->mapTo(&lamps, QPoint()), b->size());
            if (a < b && (ra & rb).width() > 1 && (ra & rb).height() > 1)
                found << QStringLiteral("%1 overlaps %2").arg(a->text(), b->text());
        }
    }
    return found.join(QLatin1Char('\n'));
}

} // namespace

TEST(TerminalLampsTest, WrapOntoMoreRowsWhenNarrowAndNeverOverlap)
{
    const Profile* dbu = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    ASSERT_NE(dbu, nullptr);
    const ParameterMeta* inputs = dbu->parameter(QStringLiteral("status.inputs"));
    ASSERT_NE(inputs, nullptr);
    QWidget window;
    auto* layout = new QVBoxLayout(&window);
    auto* lamps = new TerminalLamps(*inputs, &window);
    layout->addWidget(lamps);
    layout->addStretch(1);
    lamps->setRaw(5);
    window.resize(800, 400);
    window.show();
    QTest::qWait(50);
    EXPECT_EQ(lamps->columns(), 4); // X0–X3 side by side, as on the drive
    EXPECT_TRUE(problems(*lamps).isEmpty()) << qPrintable(problems(*lamps));
    const int oneRow = lamps->height();

    window.resize(lamps->minimumSizeHint().width() + 20, 400);
    QTest::qWait(50);
    EXPECT_LT(lamps->columns(), 4);
    EXPECT_GT(lamps->height(), oneRow); // more rows, each readable
    EXPECT_TRUE(problems(*lamps).isEmpty()) << qPrintable(problems(*lamps));
    EXPECT_EQ(lamps->stateText(), QStringLiteral("X0 ON, X1 OFF, X2 ON, X3 OFF"));
}
