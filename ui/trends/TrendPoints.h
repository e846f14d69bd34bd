#pragma once

#include "monitor/TrendHistory.h"

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
    // Widens [*lo, *hi] by 5 % (a flat line gets ±10 %, at least ±1; nothing gets 0..1).
    static void pad(double* lo, double* hi);
    // Widens [*lo, *hi] to whole steps of a round size, about `wanted` ticks; the tick count.
    static int niceTicks(double* lo, double* hi, int wanted);
};

} // namespace opentop
