#pragma once

#include "model/profile/Profile.h"
#include "model/profile/ValueContext.h"

#include <QCoreApplication>
#include <QStringList>
#include <QVector>

namespace opentop {

// The cross-parameter rule every writer passes through (the pages, the multi-drive write, a
// restore, the command line), kept in the model so that none can write around it: a value that
// other settings' allowed values depend on — the DBU's control mode decides which input
// functions exist — may only be written when each of those settings still holds a valid value
// afterwards, either the one on the drive or one written in the same operation.
class DependentValues
{
    Q_DECLARE_TR_FUNCTIONS(opentop::DependentValues)
public:
    // The settings whose allowed values depend on `meta`.
    static QStringList of(const Profile& profile, const ParameterMeta& meta);
    // What writing `raw` to `meta` would leave invalid on the drive, in words naming the settings
    // and what to do; empty when nothing. `device`: the drive's values as known (every
    // dependent not in `companions` must be known); `companions`: settings written in the same
    // operation, after `meta`.
    static QString problem(const Profile& profile, const ParameterMeta& meta, qint64 raw,
                           const ValueContext& device, const QStringList& companions);
};

} // namespace opentop
