#include "model/session/Freshness.h"

#include <QLocale>
#include <algorithm>

namespace opentop {

qint64 Freshness::staleAfterMs(int pollMs)
{
    return std::max<qint64>(kMinStaleMs, qint64(std::max(pollMs, 1)) * kStalePeriods);
}

Freshness::State Freshness::of(const QDateTime& lastAnswer, const QDateTime& now, int pollMs,
                               bool linkUp)
{
    if (!lastAnswer.isValid())
        return State::None;
    if (!linkUp || lastAnswer.msecsTo(now) > staleAfterMs(pollMs))
        return State::Stale;
    return State::Live;
}

QString Freshness::ageText(const QDateTime& lastAnswer, const QDateTime& now)
{
    if (!lastAnswer.isValid())
        return {};
    const qint64 ms = std::max<qint64>(0, lastAnswer.msecsTo(now));
    if (ms < 10000)
        return tr("%1 s old").arg(QLocale().toString(ms / 1000.0, 'f', 1));
    if (ms < 120000)
        return tr("%1 s old").arg(ms / 1000);
    if (ms < 7200000)
        return tr("%1 min old").arg(ms / 60000);
    return tr("%1 h old").arg(ms / 3600000);
}

QString Freshness::staleText(const QDateTime& lastAnswer, const QDateTime& now)
{
    if (!lastAnswer.isValid())
        return tr("never read");
    return tr("last answer %1 (%2)")
        .arg(QLocale().toString(lastAnswer.toLocalTime().time(), QStringLiteral("HH:mm:ss")),
             ageText(lastAnswer, now));
}

} // namespace opentop
