#pragma once

#include "model/monitor/TrendHistory.h"

#include <QList>
#include <QPointF>
#include <QVector>

namespace opentop {

// What a trend chart draws of a series: the points of the visible window, thinned out to what
// the plot's width can show, and value ranges with some air.
class TrendPoints
{
public:
    // The points in [fromMs, toMs] plus one either side. With more than about four per bucket
    // (pixel column), each bucket's minimum and maximum only, in time order.
    static QList<QPointF> visible(const TrendHistory::Series& series, qint64 fromMs, qint64 toMs,
                                  int buckets);
    // visible(), split where the history has a gap: two points further apart than `gapMs`
    // (polling stopped, the drive did not answer) are never joined by a line. Each segment is
    // thinned like visible(); a gap is a gap.
    static QVector<QList<QPointF>> segments(const TrendHistory::Series& series, qint64 fromMs,
                                            qint64 toMs, int buckets, qint64 gapMs);
    // Drops the points inside a run of equal values that a straight line between its
    // neighbours draws the same: a drive holding its speed costs two points, not six hundred.
    // Kept points stay at most `maxStepMs` apart (so that a gap still shows as one), and the
    // first and last point in [fromMs, toMs] stay (the value axes are fitted to those).
    static void dropRepeats(QList<QPointF>* points, qint64 fromMs, qint64 toMs, qint64 maxStepMs);
    // Widens [*lo, *hi] by 5 % (a flat line gets ±10 %, at least ±1; nothing gets 0..1).
    static void pad(double* lo, double* hi);
    // Widens [*lo, *hi] to whole steps of a round size, about `wanted` ticks; the tick count.
    static int niceTicks(double* lo, double* hi, int wanted);
};

} // namespace opentop
