#include "tests/soak/SoakGoals.h"

#include <algorithm>

namespace opentop::soak {

namespace {

double median(QVector<double> values)
{
    if (values.isEmpty())
        return 0;
    std::sort(values.begin(), values.end());
    const int n = int(values.size());
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

QString mib(qint64 kb)
{
    return QStringLiteral("%1 MiB").arg(double(kb) / 1024.0, 0, 'f', 1);
}

} // namespace

double SoakGoals::warmupS(double totalS)
{
    return std::min(kMaxWarmupS, totalS * kWarmupShare);
}

SoakGoals::Summary SoakGoals::check(const QString& name, const QVector<SoakPoint>& points,
                                    double totalS, double warmup)
{
    Summary s;
    s.name = name;
    if (warmup < 0)
        warmup = warmupS(totalS);
    // The baseline: the first point at or after the warm-up; figures after it are judged.
    int base = -1;
    for (int i = 0; i < points.size(); ++i) {
        if (points[i].elapsedS >= warmup - 1e-6) {
            base = i;
            break;
        }
    }
    if (base < 0 || points.size() - base < 3) {
        s.missed << QStringLiteral("%1: too few figure lines after the %2 s warm-up to judge "
                                   "(%3 in all)")
                        .arg(name)
                        .arg(warmup, 0, 'f', 0)
                        .arg(points.size());
        return s;
    }
    const SoakPoint& first = points[base];
    const SoakPoint& last = points.last();
    s.rssBaseKb = first.rssKb;
    s.rssEndKb = last.rssKb;
    s.rssGrowth = first.rssKb > 0 ? double(last.rssKb - first.rssKb) / double(first.rssKb) : 0;
    s.trendBaseKb = first.trendKb;
    s.trendEndKb = last.trendKb;
    s.otherGrowth = first.rssKb > 0
                        ? double(last.rssKb - first.rssKb - (last.trendKb - first.trendKb)) /
                              double(first.rssKb)
                        : 0;
    QVector<double> rates;
    for (int i = 0; i < points.size(); ++i) {
        const SoakPoint& p = points[i];
        s.lost += p.lost;
        s.rssMaxKb = std::max(s.rssMaxKb, p.rssKb);
        if (i <= base) {
            s.fdsBase = std::max(s.fdsBase, p.fds);
            s.threadsBase = std::max(s.threadsBase, p.threads);
        } else {
            rates << p.samplesPerS;
            s.staleMax = std::max(s.staleMax, p.stale);
        }
    }
    s.fdsEnd = last.fds;
    s.threadsEnd = last.threads;
    s.rateMin = *std::min_element(rates.cbegin(), rates.cend());
    s.rateMax = *std::max_element(rates.cbegin(), rates.cend());
    s.rateMedian = median(rates);
    s.rateLast = last.samplesPerS;

    if (first.rssKb <= 0 || s.otherGrowth >= kMaxRssGrowth)
        s.missed << QStringLiteral("%1: RSS grew %2 % beyond the trend histories (%3 at %4 s, "
                                   "%5 at the end, the histories %6 -> %7; goal under %8 %)")
                        .arg(name)
                        .arg(s.otherGrowth * 100, 0, 'f', 1)
                        .arg(mib(s.rssBaseKb))
                        .arg(first.elapsedS, 0, 'f', 0)
                        .arg(mib(s.rssEndKb), mib(s.trendBaseKb), mib(s.trendEndKb))
                        .arg(kMaxRssGrowth * 100, 0, 'f', 0);
    if (s.fdsEnd > s.fdsBase)
        s.missed << QStringLiteral("%1: open file descriptors grew from %2 to %3")
                        .arg(name)
                        .arg(s.fdsBase)
                        .arg(s.fdsEnd);
    if (s.threadsEnd > s.threadsBase)
        s.missed << QStringLiteral("%1: threads grew from %2 to %3")
                        .arg(name)
                        .arg(s.threadsBase)
                        .arg(s.threadsEnd);
    if (s.rateMedian <= 0)
        s.missed << QStringLiteral("%1: no samples after the warm-up").arg(name);
    else if (std::abs(s.rateLast - s.rateMedian) > kMaxRateDeviation * s.rateMedian)
        s.missed << QStringLiteral("%1: sample rate not steady: %2 samples/s in the last interval, "
                                   "median %3 (goal within %4 %)")
                        .arg(name)
                        .arg(s.rateLast, 0, 'f', 1)
                        .arg(s.rateMedian, 0, 'f', 1)
                        .arg(kMaxRateDeviation * 100, 0, 'f', 0);
    return s;
}

QStringList SoakGoals::describe(const Summary& s)
{
    QStringList lines;
    lines << QStringLiteral("%1: RSS %2 after the warm-up, %3 at the end (%4%5 %), %6 at most")
                 .arg(s.name, mib(s.rssBaseKb), mib(s.rssEndKb),
                      s.rssGrowth >= 0 ? QStringLiteral("+") : QString())
                 .arg(s.rssGrowth * 100, 0, 'f', 2)
                 .arg(mib(s.rssMaxKb));
    lines << QStringLiteral("%1: trend histories %2 -> %3; RSS growth beyond them %4%5 %")
                 .arg(s.name, mib(s.trendBaseKb), mib(s.trendEndKb),
                      s.otherGrowth >= 0 ? QStringLiteral("+") : QString())
                 .arg(s.otherGrowth * 100, 0, 'f', 2);
    lines << QStringLiteral("%1: file descriptors %2 -> %3, threads %4 -> %5")
                 .arg(s.name)
                 .arg(s.fdsBase)
                 .arg(s.fdsEnd)
                 .arg(s.threadsBase)
                 .arg(s.threadsEnd);
    lines << QStringLiteral("%1: samples/s min %2, median %3, max %4, last %5; %6 lost in all, "
                            "at most %7 drives stale after the warm-up")
                 .arg(s.name)
                 .arg(s.rateMin, 0, 'f', 1)
                 .arg(s.rateMedian, 0, 'f', 1)
                 .arg(s.rateMax, 0, 'f', 1)
                 .arg(s.rateLast, 0, 'f', 1)
                 .arg(s.lost)
                 .arg(s.staleMax);
    for (const QString& m : s.missed)
        lines << QStringLiteral("goal missed: ") + m;
    return lines;
}

} // namespace opentop::soak
