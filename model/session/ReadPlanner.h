#pragma once

#include "model/profile/Profile.h"

#include <QVector>

namespace opentop {

// One read request covering one or more parameters.
struct ReadBlockPlan
{
    quint8 function = 3;
    quint16 address = 0;
    quint16 count = 0;
    QVector<const ParameterMeta*> parameters;
};

// Groups parameter reads into as few requests as the device allows: blocks stay inside one of
// the profile's readBlocks and within maxReadRegisters; anything outside a read block is read
// on its own.
class ReadPlanner
{
public:
    static QVector<ReadBlockPlan> plan(const Profile& profile,
                                       QVector<const ParameterMeta*> parameters);
    // The same parameters, one request each (the fallback when a device refuses a block).
    static QVector<ReadBlockPlan> singles(const QVector<const ParameterMeta*>& parameters);
};

} // namespace opentop
