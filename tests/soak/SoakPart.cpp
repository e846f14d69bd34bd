#include "tests/soak/SoakPart.h"

#include <QDeadlineTimer>

namespace opentop::soak {

SoakPart::~SoakPart() = default;

bool SoakPart::isReady(int drives) const
{
    const Totals t = totals();
    return t.drives >= kReadyShare * drives && t.stale == 0 && t.samples >= t.drives;
}

bool SoakPart::buffersFull() const
{
    const Totals t = totals();
    return t.trafficFrames >= t.trafficCapacity;
}

qint64 SoakPart::nowMs()
{
    return QDeadlineTimer::current().deadline();
}

} // namespace opentop::soak
