#pragma once

#include "model/profile/Profile.h"
#include "model/profile/ValueContext.h"

#include <QCoreApplication>
#include <QStringList>
#include <QVector>
#include <functional>
#include <optional>

namespace opentop {

// One value of a setting checked before anything is sent, the same way for every writer of a
// list of values (a page's pending edits, `set`): against the values the drive will hold once
// the values before it are written (overlay()), then the serial lock and the rule of the
// settings that depend on it (DependentValues).
struct SettingCheck
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SettingCheck)
public:
    bool ok = false;
    QString error; // refused: names the allowed values
    QVector<quint16> registers;
    qint64 raw = 0;
    QString warning;   // allowed, outside the recommended range
    QString lock;      // the serial lock's warning: sent only on request
    QString dependent; // what it would leave invalid on the drive (DependentValues)

    // `text` for `meta`, validated against `context`; `companions`: the settings written with
    // it, after it (they do not count as left invalid).
    static SettingCheck of(const Profile& profile, const ParameterMeta& meta, const QString& text,
                           const ValueContext& context, const QStringList& companions);
    // `base` with the values of `pending` (by name, raw) in front of the drive's.
    static ValueContext overlay(const ValueContext& base,
                                std::function<std::optional<qint64>(const QString&)> pending);
};

} // namespace opentop
