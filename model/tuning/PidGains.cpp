#include "model/tuning/PidGains.h"

#include <QCoreApplication>

namespace opentop {

QString PidGains::toString() const
{
    return QCoreApplication::translate("opentop::PidGains", "P %1, I %2, D %3, D period %4 ms")
        .arg(p, 0, 'f', 4)
        .arg(i, 0, 'f', 4)
        .arg(d, 0, 'f', 4)
        .arg(dPeriodMs);
}

} // namespace opentop
