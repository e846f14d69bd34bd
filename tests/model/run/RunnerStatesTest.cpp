// The runners' state helper on its own: states entered by name, late answers and timers of a
// state that ended dropped, poll loops that keep their period and free themselves.
#include "model/run/RunnerStates.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <gtest/gtest.h>

#include <functional>
#include <memory>

using namespace opentop;

namespace {

enum State
{
    First,
    Second,
    Third
};

void spin(int ms)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
}

bool spinUntil(const std::function<bool()>& done, int maxMs = 2000)
{
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < maxMs)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    return done();
}

} // namespace

TEST(RunnerStates, StartEntersTheFirstStateOnlyAfterStartReturns)
{
    RunnerStates states(QStringLiteral("test"));
    bool entered = false;
    states.add(First, "first", [&] { entered = true; });
    states.start(First);
    EXPECT_FALSE(entered);
    EXPECT_FALSE(states.isActive());
    ASSERT_TRUE(spinUntil([&] { return entered; }));
    EXPECT_EQ(states.state(), First);
    EXPECT_EQ(states.stateName(), QStringLiteral("first"));
}

TEST(RunnerStates, AnAnswerToAStateThatEndedIsDropped)
{
    RunnerStates states(QStringLiteral("test"));
    std::function<void(int)> pending;
    int handled = -1;
    states.add(First, "first", [&] { pending = states.guard([&](int v) { handled = v; }); });
    states.add(Second, "second", nullptr);
    states.start(First);
    ASSERT_TRUE(spinUntil([&] { return bool(pending); }));
    states.go(Second);
    pending(7); // a late reply to the first state's request
    EXPECT_EQ(handled, -1);
    // Re-entering the same state is a new entry: the old answer is still dropped.
    states.go(First);
    std::function<void(int)> stale = pending;
    states.go(First);
    stale(8);
    EXPECT_EQ(handled, -1);
    pending(9);
    EXPECT_EQ(handled, 9);
    states.end();
    pending(10);
    EXPECT_EQ(handled, 9);
    EXPECT_EQ(states.trail(), QStringList({QStringLiteral("first"), QStringLiteral("second"),
                                           QStringLiteral("first"), QStringLiteral("first")}));
}

TEST(RunnerStates, ATimeoutBelongsToItsState)
{
    RunnerStates states(QStringLiteral("test"));
    int fired = 0;
    states.add(First, "first", [&] { states.after(30, [&] { ++fired; }); });
    states.add(Second, "second", [&] { states.after(30, [&] { fired += 10; }); });
    states.start(First);
    ASSERT_TRUE(spinUntil([&] { return states.isActive(); }));
    states.go(Second); // the first state's timeout must not fire
    spin(100);
    EXPECT_EQ(fired, 10);
}

TEST(RunnerStates, APollLoopKeepsItsPeriodAndEndsWithItsStateAndFreesItself)
{
    RunnerStates states(QStringLiteral("test"));
    QVector<qint64> rounds;
    QElapsedTimer clock;
    auto alive = std::make_shared<int>(0);
    std::weak_ptr<int> watch = alive;
    states.add(First, "first", [&, alive]() mutable {
        states.every(40, [&, alive](std::function<void()> again) {
            rounds << clock.elapsed();
            // An answer that takes 15 ms: the period is kept from the loop's start.
            QTimer::singleShot(15, &states, again);
        });
        alive.reset();
    });
    states.add(Second, "second", nullptr);
    alive.reset(); // only the loop's rounds hold it now
    clock.start();
    states.start(First);
    ASSERT_TRUE(spinUntil([&] { return rounds.size() >= 5; }));
    states.go(Second);
    const int seen = rounds.size();
    spin(150);
    EXPECT_EQ(rounds.size(), seen) << "the loop went on after its state ended";
    for (int k = 1; k < 5; ++k)
        EXPECT_NEAR(rounds[k] - rounds[0], 40 * k, 25) << "round " << k;
    spin(60); // the last round's answer and timer are gone
    EXPECT_TRUE(watch.expired()) << "the loop still holds what its rounds captured";
}

TEST(RunnerStates, TheMotionFlagSaysWhetherAnExitMustStopTheMotor)
{
    RunnerStates states(QStringLiteral("test"));
    states.add(First, "first", nullptr);
    states.start(First);
    EXPECT_FALSE(states.motionMayBeOn());
    states.motionSent();
    EXPECT_TRUE(states.motionMayBeOn());
    states.stopConfirmed();
    EXPECT_FALSE(states.motionMayBeOn());
    EXPECT_TRUE(states.motionEverSent());
    states.start(First); // a new run forgets the last one's
    EXPECT_FALSE(states.motionEverSent());
}

TEST(RunnerStates, AnUnknownStateEndsTheRunner)
{
    RunnerStates states(QStringLiteral("test"));
    states.add(First, "first", nullptr);
    states.start(First);
    ASSERT_TRUE(spinUntil([&] { return states.isActive(); }));
    states.go(Third);
    EXPECT_FALSE(states.isActive());
}

TEST(RunnerStates, StartNowEntersAtOnceAndAnAnswerAfterTheRunnerIsGoneIsDropped)
{
    std::function<void()> late;
    bool ran = false;
    {
        RunnerStates states(QStringLiteral("test"));
        states.add(First, "first", [&] { late = states.guard([&] { ran = true; }); });
        states.startNow(First);
        EXPECT_EQ(states.state(), First);
        ASSERT_TRUE(late);
    }
    late(); // the reply to a runner destroyed mid-request
    EXPECT_FALSE(ran);
}

TEST(RunnerStates, APollLoopWithoutAPeriodAsksAgainAsSoonAsItWasAnswered)
{
    RunnerStates states(QStringLiteral("test"));
    int rounds = 0;
    states.add(First, "first", [&] {
        states.every(0, [&](std::function<void()> again) {
            ++rounds;
            QTimer::singleShot(0, &states, again);
        });
    });
    states.startNow(First);
    ASSERT_TRUE(spinUntil([&] { return rounds >= 20; }, 1000));
    states.end();
    const int seen = rounds;
    spin(50);
    EXPECT_EQ(rounds, seen);
}
