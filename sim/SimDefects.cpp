#include "sim/SimDefects.h"

#include "model/profile/Profile.h"
#include "sim/SimDevice.h"

#include <QRegularExpression>
#include <algorithm>

namespace opentop {

namespace {

// "Over speed" -> "over_speed".
QString slug(const QString& name)
{
    static const QRegularExpression other(QStringLiteral("[^a-z0-9]+"));
    QString s = name.toLower();
    s.replace(other, QStringLiteral("_"));
    while (s.endsWith(QLatin1Char('_')))
        s.chop(1);
    return s;
}

// A writable parameter named `text` or whose registers include the address `text`.
const ParameterMeta* writableParameter(const Profile& profile, const QString& text)
{
    if (const ParameterMeta* p = profile.parameter(text))
        return p->isWritable() ? p : nullptr;
    const std::optional<qint64> address = SimDevice::parseNumber(text);
    if (!address)
        return nullptr;
    for (const ParameterMeta& p : profile.parameters) {
        if (p.isWritable() && *address >= p.address && *address < p.address + p.registerCount)
            return &p;
    }
    return nullptr;
}

QString settingExamples(const Profile& profile)
{
    QStringList names;
    for (const ParameterMeta& p : profile.parameters) {
        if (p.isWritable() && p.kind == QLatin1String("setting") && names.size() < 4)
            names << p.name;
    }
    return names.join(QStringLiteral(", "));
}

} // namespace

double SimDefects::reachable(double magnitude) const
{
    if (stall)
        return 0;
    return maxSpeed ? std::min(magnitude, *maxSpeed) : magnitude;
}

std::optional<SimDefects> SimDefects::resolve(const SimDefectSpec& spec, const Profile& profile,
                                              QString* error)
{
    auto failed = [error](const QString& message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    SimDefects d;
    d.spec = spec;
    d.spec.clear = false;
    d.firmware = spec.firmware ? std::optional<quint16>(quint16(*spec.firmware)) : std::nullopt;
    if (spec.firmware && !profile.parameter(profile.identify.versionParameter))
        return failed(tr("a %1 reports no firmware version").arg(profile.family));
    if (spec.maxSpeed)
        d.maxSpeed = *spec.maxSpeed;
    d.stall = spec.stall;
    d.turnaroundMs = spec.turnaroundMs;
    d.loadOffset = spec.loadOffset.value_or(0);
    d.loadScale = spec.loadScale.value_or(1);
    if (!spec.alarm.isEmpty()) {
        const CodeTable* table = profile.codeTable(QStringLiteral("alarm"));
        if (!table) {
            // The DC controller has no alarm codes: its one protection is the stall stop.
            if (spec.alarm != QLatin1String("stall"))
                return failed(tr("alarm=%1: a %2 has no alarm codes; its protection is the stall "
                                 "stop: write alarm=stall@TIME")
                                  .arg(spec.alarm, profile.family));
            d.alarmCode = 0;
        } else {
            const std::optional<qint64> number = SimDevice::parseNumber(spec.alarm);
            QStringList allowed;
            for (const CodeEntry& e : table->entries) {
                if ((number && e.code == *number) || slug(e.name) == spec.alarm)
                    d.alarmCode = int(e.code);
                allowed << QStringLiteral("0x%1 %2")
                               .arg(e.code, 2, 16, QLatin1Char('0'))
                               .arg(slug(e.name));
            }
            if (!d.alarmCode)
                return failed(
                    tr("alarm=%1: not an alarm of a %2; allowed: %3")
                        .arg(spec.alarm, profile.family, allowed.join(QStringLiteral(", "))));
        }
        d.alarmAfterMs = spec.alarmAfterMs;
    }
    for (const QStringList* list : {&spec.noStick, &spec.noStore}) {
        const bool stick = list == &spec.noStick;
        for (const QString& text : *list) {
            const ParameterMeta* p = writableParameter(profile, text);
            if (!p)
                return failed(
                    tr("%1=%2: no writable parameter of a %3 has this name or address; "
                       "e.g. %4")
                        .arg(stick ? QStringLiteral("nostick") : QStringLiteral("nostore"), text,
                             profile.family, settingExamples(profile)));
            QStringList& names = stick ? d.noStick : d.noStore;
            if (!names.contains(p->name))
                names << p->name;
        }
    }
    return d;
}

} // namespace opentop
