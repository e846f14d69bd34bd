// The one stale look of every live view: grey text and the "stale" property, the age told.
#include "ui/widgets/StaleLook.h"

#include <QLabel>
#include <gtest/gtest.h>

namespace opentop {

TEST(StaleLookTest, GreysAWidgetAndGivesItsOwnColourBack)
{
    QWidget parent;
    auto* label = new QLabel(QStringLiteral("1500 r/min"), &parent);
    const QColor normal = label->palette().color(QPalette::WindowText);
    ASSERT_NE(normal, StaleLook::grey());
    StaleLook::apply(label, true);
    EXPECT_TRUE(StaleLook::isStale(label));
    EXPECT_EQ(label->palette().color(QPalette::WindowText), StaleLook::grey());
    StaleLook::apply(label, false);
    EXPECT_FALSE(StaleLook::isStale(label));
    EXPECT_EQ(label->palette().color(QPalette::WindowText), normal);
}

TEST(StaleLookTest, TellsTheAgeOfALiveValueAndTheLastAnswerOfAStaleOne)
{
    const QDateTime read = QDateTime::fromMSecsSinceEpoch(1'700'000'000'000);
    EXPECT_EQ(StaleLook::ageText(Freshness::State::Live, read, read.addMSecs(400)),
              QStringLiteral("updated 0.4 s ago"));
    const QString stale = StaleLook::ageText(Freshness::State::Stale, read, read.addSecs(12));
    EXPECT_TRUE(stale.startsWith(QStringLiteral("last answer "))) << qPrintable(stale);
    EXPECT_TRUE(stale.contains(QStringLiteral("12 s old"))) << qPrintable(stale);
    EXPECT_EQ(StaleLook::ageText(Freshness::State::None, QDateTime(), read),
              QStringLiteral("not read yet"));
}

TEST(StaleLookTest, FollowsItsSourceAndGreysItsWidgets)
{
    QWidget view;
    auto* value = new QLabel(&view);
    Freshness::State state = Freshness::State::Live;
    const QDateTime read = QDateTime::currentDateTimeUtc();
    StaleLook look([&state](const QDateTime&) { return state; }, [read] { return read; }, nullptr);
    look.addWidget(value);
    int changes = 0;
    QObject::connect(&look, &StaleLook::stateChanged, [&changes] { ++changes; });
    look.update();
    EXPECT_FALSE(StaleLook::isStale(value));
    EXPECT_TRUE(look.ageText().startsWith(QStringLiteral("updated")));
    state = Freshness::State::Stale;
    look.update();
    EXPECT_TRUE(StaleLook::isStale(value));
    EXPECT_TRUE(look.ageText().startsWith(QStringLiteral("last answer")));
    state = Freshness::State::Live;
    look.update();
    EXPECT_FALSE(StaleLook::isStale(value));
    EXPECT_EQ(changes, 3); // none to live, to stale, to live
}

} // namespace opentop
