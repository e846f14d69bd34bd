#include "model/tuning/TuningSpec.h"

#include "model/profile/Profile.h"

#include <QJsonArray>
#include <QJsonObject>

namespace opentop {

const TuningSpec::ClosedLoopMode* TuningSpec::closedLoop(int mode) const
{
    for (const ClosedLoopMode& m : closedLoopModes) {
        if (m.mode == mode)
            return &m;
    }
    return nullptr;
}

std::optional<TuningSpec> TuningSpec::of(const Profile& profile, QString* error)
{
    const QJsonObject t = profile.tuning;
    if (t.isEmpty()) {
        *error = tr("%1 has no speed loop to tune").arg(profile.name);
        return std::nullopt;
    }
    TuningSpec s;
    s.periodMs = t.value(QStringLiteral("periodMs")).toInt(0);
    s.outputFullScale = t.value(QStringLiteral("outputFullScale")).toDouble(0);
    s.openLoopMode = t.value(QStringLiteral("openLoopMode")).toInt(-1);
    for (const QJsonValue& v : t.value(QStringLiteral("closedLoopModes")).toArray()) {
        const QJsonObject o = v.toObject();
        s.closedLoopModes.append({o.value(QStringLiteral("mode")).toInt(-1),
                                  o.value(QStringLiteral("feedback")).toString()});
    }
    const auto role = [&](const char* name, QString* into, qint64* value = nullptr) {
        const ProfileRole* r = profile.role(QString::fromLatin1(name));
        if (!r || r->parameter.isEmpty())
            return false;
        *into = r->parameter;
        if (value)
            *value = r->value.value_or(1);
        return true;
    };
    const bool roles = role("pidP", &s.gainP) && role("pidI", &s.gainI) && role("pidD", &s.gainD) &&
                       role("pidDPeriod", &s.dPeriod) &&
                       role("pidStore", &s.store, &s.storeValue) &&
                       role("speedMode", &s.speedMode) && role("speedCommand", &s.command) &&
                       role("commLossTime", &s.commLossTime) &&
                       role("loadCurrent", &s.loadCurrent) && role("output", &s.output);
    if (!roles) {
        *error = tr("%1: the profile's tuning needs the roles pidP, pidI, pidD, pidDPeriod, "
                    "pidStore, speedMode, speedCommand, commLossTime, loadCurrent and output")
                     .arg(profile.name);
        return std::nullopt;
    }
    role("currentLimit", &s.currentLimit); // optional
    bool feedbackKnown = !s.closedLoopModes.isEmpty();
    for (const ClosedLoopMode& m : s.closedLoopModes)
        feedbackKnown = feedbackKnown && m.mode >= 0 && profile.parameter(m.feedback);
    if (s.periodMs < 1 || s.outputFullScale <= 0 || s.openLoopMode < 0 || !feedbackKnown) {
        *error = tr("%1: the profile's tuning section needs periodMs ≥ 1, outputFullScale > 0, "
                    "openLoopMode and closedLoopModes with known feedback parameters")
                     .arg(profile.name);
        return std::nullopt;
    }
    return s;
}

} // namespace opentop
