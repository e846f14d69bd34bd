#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QString>

namespace opentop {

// The one rule every view follows for a live value: how old it is, and whether it may still be
// shown as live. A value is Live while it is younger than a few poll periods and the link is
// up; after that it is Stale (grey, with the time of the last answer); a value never read is
// None. Lamps and lights show grey, never green, for anything but Live.
class Freshness
{
    Q_DECLARE_TR_FUNCTIONS(Freshness)
public:
    enum class State { None, Live, Stale };

    // Poll periods without an answer after which a value is stale.
    static constexpr int kStalePeriods = 3;
    // Never stale sooner than this (fast polling on a busy bus is not a lost link).
    static constexpr qint64 kMinStaleMs = 1500;

    // `lastAnswer`: when the value was read (invalid: never); `pollMs`: the polling interval of
    // the view's source; `linkUp`: the connection is open and the drive answers.
    static State of(const QDateTime& lastAnswer, const QDateTime& now, int pollMs, bool linkUp);
    static qint64 staleAfterMs(int pollMs);

    // "0.4 s old", "12 s old", "5 min old"; empty for an invalid time.
    static QString ageText(const QDateTime& lastAnswer, const QDateTime& now);
    // What a stale value says about itself: "last answer 10:31:05 (12 s ago)".
    static QString staleText(const QDateTime& lastAnswer, const QDateTime& now);
};

} // namespace opentop
