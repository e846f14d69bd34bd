#include "ui/trends/TrendPoints.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

// The points [first, end) of `p`; with more than about four per bucket (pixel column), each
// bucket's minimum and maximum only, in time order.
QList<QPointF> thinned(const QVector<TrendHistory::Point>& p, int first, int end, qint64 fromMs,
                       qint64 toMs, int buckets)
{
    QList<QPointF> points;
    const int n = end - first;
    buckets = std::max(1, buckets);
    if (n <= 4 * buckets || toMs <= fromMs) {
        points.reserve(std::max(0, n));
        for (int i = first; i < end; ++i)
            points << QPointF(double(p[i].ms), p[i].value);
        return points;
    }
    // Minimum and maximum of each bucket, in time order: spikes stay visible.
    const double width = double(toMs - fromMs) / buckets;
    int i = first;
    while (i < end) {
        const double bucket = std::floor(double(p[i].ms - fromMs) / width) + 1;
        const qint64 bucketEnd = fromMs + qint64(bucket * width);
        int lo = i;
        int hi = i;
        int j = i;
        for (; j < end && p[j].ms < bucketEnd; ++j) {
            lo = p[j].value < p[lo].value ? j : lo;
            hi = p[j].value > p[hi].value ? j : hi;
        }
        for (int k : {std::min(lo, hi), std::max(lo, hi)}) {
            if (points.isEmpty() || points.last().x() < double(p[k].ms))
                points << QPointF(double(p[k].ms), p[k].value);
        }
        i = std::max(j, i + 1);
    }
    return points;
}

} // namespace

QList<QPointF> TrendPoints::visible(const TrendHistory::Series& series, qint64 fromMs, qint64 toMs,
                                    int buckets)
{
    const QVector<TrendHistory::Point>& p = series.points;
    if (p.isEmpty())
        return {};
    // One point either side of the window, so that the line reaches its edges.
    const int first = std::max(0, TrendHistory::lowerBound(series, fromMs) - 1);
    const int end = std::min(int(p.size()), TrendHistory::lowerBound(series, toMs + 1) + 1);
    return thinned(p, first, end, fromMs, toMs, buckets);
}

QVector<QList<QPointF>> TrendPoints::segments(const TrendHistory::Series& series, qint64 fromMs,
                                              qint64 toMs, int buckets, qint64 gapMs)
{
    const QVector<TrendHistory::Point>& p = series.points;
    QVector<QList<QPointF>> out;
    if (p.isEmpty())
        return out;
    const int first = std::max(0, TrendHistory::lowerBound(series, fromMs) - 1);
    const int end = std::min(int(p.size()), TrendHistory::lowerBound(series, toMs + 1) + 1);
    int start = first;
    for (int i = first + 1; i <= end; ++i) {
        if (i < end && p[i].ms - p[i - 1].ms <= gapMs)
            continue;
        // The buckets of a segment are as wide as those of the whole window.
        const qint64 from = std::max(fromMs, p[start].ms);
        const qint64 to = std::min(toMs, p[i - 1].ms);
        const int share =
            toMs > fromMs && to > from
                ? std::max(1, int(double(buckets) * double(to - from) / double(toMs - fromMs)))
                : 1;
        out << thinned(p, start, i, from, to, share);
        start = i;
    }
    return out;
}

void TrendPoints::dropRepeats(QList<QPointF>* points, qint64 fromMs, qint64 toMs, qint64 maxStepMs)
{
    QList<QPointF>& p = *points;
    if (p.size() < 3)
        return;
    int firstIn = -1;
    int lastIn = -1;
    for (int i = 0; i < p.size(); ++i) {
        if (p[i].x() >= double(fromMs) && p[i].x() <= double(toMs)) {
            firstIn = firstIn < 0 ? i : firstIn;
            lastIn = i;
        }
    }
    QList<QPointF> kept;
    kept.reserve(p.size());
    kept << p.first();
    for (int i = 1; i + 1 < p.size(); ++i) {
        const bool repeat = p[i].y() == kept.last().y() && p[i].y() == p[i + 1].y() &&
                            p[i + 1].x() - kept.last().x() <= double(maxStepMs);
        if (!repeat || i == firstIn || i == lastIn)
            kept << p[i];
    }
    kept << p.last();
    p = std::move(kept);
}

void TrendPoints::pad(double* lo, double* hi)
{
    if (*lo > *hi) {
        *lo = 0;
        *hi = 1;
    } else if (*hi - *lo < 1e-9) {
        // A flat line in the middle, not on the frame.
        const double air = std::max(1.0, std::abs(*hi) * 0.1);
        *lo -= air;
        *hi += air;
    } else {
        // Not across zero when the values do not cross it: no empty band below a speed ramp.
        const double air = (*hi - *lo) * 0.05;
        *lo = *lo >= 0 ? std::max(0.0, *lo - air) : *lo - air;
        *hi = *hi <= 0 ? std::min(0.0, *hi + air) : *hi + air;
    }
}

int TrendPoints::niceTicks(double* lo, double* hi, int wanted)
{
    // Steps of 1, 2, 2.5 or 5 × 10^n: labels people read at a glance.
    const double raw = (*hi - *lo) / std::max(1, wanted - 1);
    if (!(raw > 0))
        return 2;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10 * magnitude;
    for (double f : {1.0, 2.0, 2.5, 5.0}) {
        if (f * magnitude >= raw) {
            step = f * magnitude;
            break;
        }
    }
    *lo = std::floor(*lo / step) * step;
    *hi = std::ceil(*hi / step) * step;
    return int(std::lround((*hi - *lo) / step)) + 1;
}

} // namespace opentop
