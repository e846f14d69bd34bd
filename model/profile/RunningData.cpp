#include "model/profile/RunningData.h"

#include <cmath>

#include "model/profile/Profile.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"

#include <QRegularExpression>

namespace opentop {

namespace {

std::optional<double> numberOf(const Profile& profile, const QString& name,
                               std::optional<qint64> raw)
{
    const ParameterMeta* meta = profile.parameter(name);
    if (!meta || !raw)
        return std::nullopt;
    return double(*raw) * meta->spec.scale;
}

} // namespace

QString RunningData::parameter(const Profile& profile, int spno, const QString& field)
{
    const QString name = QStringLiteral("spno%1.%2").arg(spno).arg(field);
    return profile.parameter(name) ? name : QString();
}

int RunningData::count(const Profile& profile)
{
    int n = 0;
    while (!parameter(profile, n + 1, QStringLiteral("speed")).isEmpty())
        ++n;
    return n;
}

int RunningData::spnoOf(const QString& name, QString* field)
{
    static const QRegularExpression re(QStringLiteral("^spno(\\d+)\\.(\\w+)$"));
    const QRegularExpressionMatch m = re.match(name);
    if (!m.hasMatch())
        return 0;
    if (field)
        *field = m.captured(2);
    return m.captured(1).toInt();
}

std::optional<int>
RunningData::selected(const Profile& profile,
                      const std::function<std::optional<double>(const QString&)>& raw)
{
    const ProfileRole* role = profile.role(QStringLiteral("selected"));
    const ParameterMeta* meta = RoleEvaluator::parameter(profile, QStringLiteral("selected"));
    const std::optional<double> value = meta ? raw(meta->name) : std::nullopt;
    if (!role || !value)
        return std::nullopt;
    qint64 code = qint64(*value);
    if (!role->field.isEmpty()) {
        const BitField* field = RoleEvaluator::bitField(*meta, role->field);
        if (!field)
            return std::nullopt;
        code = RoleEvaluator::fieldValue(*field, *value);
    }
    return int(code) + 1; // running data N is code N-1
}

QString RunningData::decelerationWarning(int spno, std::optional<double> speedRpm,
                                         std::optional<double> decelerationS)
{
    if (!speedRpm || !decelerationS || *speedRpm < kHighSpeedRpm ||
        *decelerationS >= kMinDecelerationS - 1e-9)
        return {};
    return tr("SPno%1 slows down from %2 r/min in %3 s: the manual asks for a deceleration time "
              "of more than %4 s when slowing down from high speed (about %5 r/min and above).")
        .arg(spno)
        .arg(ValueCodec::formatNumber(*speedRpm, 0), ValueCodec::formatNumber(*decelerationS, 1),
             ValueCodec::formatNumber(kMinDecelerationS, 0),
             ValueCodec::formatNumber(kHighSpeedRpm, 0));
}

QString RunningData::warningFor(const Profile& profile, const QString& name, qint64 raw,
                                const ValueContext& values)
{
    QString field;
    const int spno = spnoOf(name, &field);
    if (spno == 0 || (field != QLatin1String("speed") && field != QLatin1String("decel")))
        return {};
    const QString speed = parameter(profile, spno, QStringLiteral("speed"));
    const QString decel = parameter(profile, spno, QStringLiteral("decel"));
    if (speed.isEmpty() || decel.isEmpty())
        return {};
    const bool isSpeed = field == QLatin1String("speed");
    return decelerationWarning(
        spno, numberOf(profile, speed, isSpeed ? std::optional(raw) : values.rawOf(speed)),
        numberOf(profile, decel, isSpeed ? values.rawOf(decel) : std::optional(raw)));
}

QStringList RunningData::warnings(const Profile& profile, const ValueContext& values)
{
    QStringList list;
    for (int spno = 1; spno <= count(profile); ++spno) {
        const QString speed = parameter(profile, spno, QStringLiteral("speed"));
        const QString decel = parameter(profile, spno, QStringLiteral("decel"));
        if (decel.isEmpty())
            continue;
        const QString w = decelerationWarning(spno, numberOf(profile, speed, values.rawOf(speed)),
                                              numberOf(profile, decel, values.rawOf(decel)));
        if (!w.isEmpty())
            list << w;
    }
    return list;
}

QString RunningData::summary(const Profile& profile, const ValueContext& values)
{
    QStringList spnos;
    double lowSpeed = 0, highSpeed = 0, shortest = 0, longest = 0;
    for (int spno = 1; spno <= count(profile); ++spno) {
        const QString speed = parameter(profile, spno, QStringLiteral("speed"));
        const QString decel = parameter(profile, spno, QStringLiteral("decel"));
        if (decel.isEmpty())
            continue;
        const std::optional<double> rpm = numberOf(profile, speed, values.rawOf(speed));
        const std::optional<double> s = numberOf(profile, decel, values.rawOf(decel));
        if (decelerationWarning(spno, rpm, s).isEmpty())
            continue;
        const double v = std::abs(*rpm);
        lowSpeed = spnos.isEmpty() ? v : std::min(lowSpeed, v);
        highSpeed = spnos.isEmpty() ? v : std::max(highSpeed, v);
        shortest = spnos.isEmpty() ? *s : std::min(shortest, *s);
        longest = spnos.isEmpty() ? *s : std::max(longest, *s);
        spnos << QStringLiteral("SPno%1").arg(spno);
    }
    if (spnos.isEmpty())
        return {};
    const auto range = [](double a, double b, int decimals) {
        return a == b ? ValueCodec::formatNumber(a, decimals)
                      : ValueCodec::formatNumber(a, decimals) + QChar(0x2013) +
                            ValueCodec::formatNumber(b, decimals);
    };
    return tr("Short deceleration from high speed on %1 (%2 r/min in %3 s): the manual asks for "
              "a deceleration time of more than %4 s when slowing down from high speed (about %5 "
              "r/min and above).")
        .arg(spnos.join(QStringLiteral(", ")), range(lowSpeed, highSpeed, 0),
             range(shortest, longest, 1), ValueCodec::formatNumber(kMinDecelerationS, 0),
             ValueCodec::formatNumber(kHighSpeedRpm, 0));
}

} // namespace opentop
