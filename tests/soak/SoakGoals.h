#pragma once

#include <QString>
#include <QStringList>
#include <QVector>

namespace opentop::soak {

// One figure line of one measured process.
struct SoakPoint
{
    double elapsedS = 0; // since monitoring of every drive began
    qint64 rssKb = 0;
    int fds = 0;
    int threads = 0;
    double samplesPerS = 0; // over the interval that ends here (0 at the first point)
    qint64 lost = 0;        // failed polls in that interval
    int stale = 0;          // drives whose values were not live at this moment
    qint64 trendKb = 0;     // what the trend histories hold (points x their size)
};

// The soak's goals, checked on the figure lines of one process: after the warm-up (the first
// five minutes, or the first 20 % of a shorter run) resident memory grows less than 5 %, the
// open file descriptors and threads do not grow, and the sample rate stays steady (the last
// interval's rate within 10 % of the median of the intervals after the warm-up).
// The trend histories keep every drive's values by design (an hour at 10 Hz per series, see
// TrendHistory), so they grow for the whole of an hour at a slow poll: their own growth (their
// points times the point's size) is shown and left out of the memory goal; the rest is judged.
class SoakGoals
{
public:
    static constexpr double kMaxWarmupS = 300.0;
    static constexpr double kWarmupShare = 0.2;
    static constexpr double kMaxRssGrowth = 0.05;
    static constexpr double kMaxRateDeviation = 0.10;

    struct Summary
    {
        QString name;
        qint64 rssBaseKb = 0; // at the end of the warm-up
        qint64 rssEndKb = 0;
        qint64 rssMaxKb = 0;
        double rssGrowth = 0; // (end - base) / base
        qint64 trendBaseKb = 0;
        qint64 trendEndKb = 0;
        double otherGrowth = 0; // (end - base - trend history growth) / base: the goal
        int fdsBase = 0;        // the most during the warm-up
        int fdsEnd = 0;
        int threadsBase = 0; // likewise
        int threadsEnd = 0;
        double rateMin = 0; // over the intervals after the warm-up
        double rateMedian = 0;
        double rateMax = 0;
        double rateLast = 0;
        qint64 lost = 0;    // over the whole run
        int staleMax = 0;   // after the warm-up
        QStringList missed; // the goals missed, each named with its figures
    };

    // The warm-up for a run of `totalS` seconds.
    static double warmupS(double totalS);
    // Checks `points` (in time order, the first at 0 s) of the process called `name`, after a
    // warm-up of `warmup` seconds (negative: warmupS(totalS)).
    static Summary check(const QString& name, const QVector<SoakPoint>& points, double totalS,
                         double warmup = -1);
    // The summary as text lines (figures, then "goal missed: ..." lines).
    static QStringList describe(const Summary& summary);
};

} // namespace opentop::soak
