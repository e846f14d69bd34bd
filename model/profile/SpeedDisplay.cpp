#include "model/profile/SpeedDisplay.h"

#include "model/profile/Profile.h"
#include "model/profile/ValueCodec.h"

#include <cmath>

namespace opentop {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMmPerMeter = 1000;
constexpr double kMmPerYard = 914.4;

// Upper ends of the speed sections ro-0..ro-2 (r/min); ro-3 covers everything above.
constexpr double kSectionTop[] = {500, 1000, 2000};

} // namespace

SpeedDisplay::Names SpeedDisplay::Names::withPrefix(const QString& prefix)
{
    Names n;
    auto name = [&prefix](const char* suffix) { return prefix + QLatin1String(suffix); };
    n.mode = name("mode");
    n.reduction = name("reduction");
    n.increase = name("increase");
    n.decimals = name("decimals");
    n.diameterYard = name("diameter_yard");
    n.diameterMeter = name("diameter_meter");
    n.timeDiameter = name("time_diameter");
    n.distanceUnit = name("distance_unit");
    n.distance = name("distance");
    n.timeUnit = name("time_unit");
    for (int i = 0; i < 4; ++i)
        n.corrections << prefix + QStringLiteral("ro%1").arg(i);
    return n;
}

QStringList SpeedDisplay::Names::all() const
{
    return QStringList{mode,          reduction,    increase,     decimals, diameterYard,
                       diameterMeter, timeDiameter, distanceUnit, distance, timeUnit} +
           corrections;
}

bool SpeedDisplay::supported(const Profile& profile, const Names& names)
{
    for (const QString& n : names.all()) {
        const ParameterMeta* meta = profile.parameter(n);
        if (!meta || !meta->isReadable())
            return false;
    }
    return true;
}

std::optional<SpeedDisplay>
SpeedDisplay::fromValues(const Names& names,
                         const std::function<std::optional<double>(const QString&)>& value,
                         QString* error, const std::function<QString(const QString&)>& nameFor)
{
    QStringList missing;
    auto get = [&](const QString& name, double fallback) {
        const std::optional<double> v = value(name);
        if (!v)
            missing << (nameFor ? nameFor(name) : name);
        return v.value_or(fallback);
    };
    Settings s;
    const int mode = int(get(names.mode, 0));
    s.reduction = get(names.reduction, 1);
    s.increase = get(names.increase, 1);
    s.decimals = int(get(names.decimals, 3));
    for (int i = 0; i < 4 && i < names.corrections.size(); ++i)
        s.corrections[i] = int(get(names.corrections.at(i), 0));
    // Only what the chosen unit uses must be known.
    if (mode == int(Mode::LinearYard))
        s.diameterYard = get(names.diameterYard, 0);
    if (mode == int(Mode::LinearMeter))
        s.diameterMeter = get(names.diameterMeter, 0);
    if (mode == int(Mode::Time)) {
        s.timeDiameter = get(names.timeDiameter, 0);
        s.distance = get(names.distance, 0);
        s.distanceInYards = get(names.distanceUnit, 0) == 1;
        s.timeInSeconds = get(names.timeUnit, 0) == 1;
    }
    QString problem;
    if (!missing.isEmpty())
        problem =
            tr("speed display settings not known: %1").arg(missing.join(QStringLiteral(", ")));
    else if (mode < 0 || mode > 3)
        problem = tr("speed display unit code %1 is unknown (0–3)").arg(mode);
    else if (!(s.reduction > 0) || !(s.increase > 0))
        problem = tr("speed display ratios must be positive (reduction %1, increase %2)")
                      .arg(s.reduction)
                      .arg(s.increase);
    else if (s.decimals < 0 || s.decimals > 3)
        problem = tr("speed display decimals %1 outside 0–3").arg(s.decimals);
    if (!problem.isEmpty()) {
        if (error)
            *error = problem;
        return std::nullopt;
    }
    s.mode = Mode(mode);
    return SpeedDisplay(s);
}

int SpeedDisplay::section(double motorRpm)
{
    const double magnitude = std::abs(motorRpm);
    if (magnitude == 0)
        return -1;
    for (int i = 0; i < 3; ++i) {
        if (magnitude <= kSectionTop[i])
            return i;
    }
    return 3;
}

double SpeedDisplay::correctedMotorRpm(double motorRpm) const
{
    const int s = section(motorRpm);
    if (s < 0)
        return 0;
    const double magnitude = std::max(0.0, std::abs(motorRpm) + m_settings.corrections[s]);
    return motorRpm < 0 ? -magnitude : magnitude;
}

double SpeedDisplay::shaftRpm(double motorRpm) const
{
    return correctedMotorRpm(motorRpm) / m_settings.reduction * m_settings.increase;
}

QString SpeedDisplay::unit() const
{
    switch (m_settings.mode) {
    case Mode::Rpm:
        return QStringLiteral("r/min");
    case Mode::LinearYard:
        return QStringLiteral("yd/min");
    case Mode::LinearMeter:
        return QStringLiteral("m/min");
    case Mode::Time:
        return m_settings.timeInSeconds ? QStringLiteral("s") : QStringLiteral("min:s");
    }
    return QString();
}

SpeedDisplay::Shown SpeedDisplay::show(double motorRpm) const
{
    Shown shown;
    shown.unit = unit();
    const double shaft = shaftRpm(motorRpm);
    const int decimals = m_settings.decimals;
    switch (m_settings.mode) {
    case Mode::Rpm:
        shown.value = shaft;
        break;
    case Mode::LinearYard:
        shown.value = shaft * kPi * m_settings.diameterYard / kMmPerYard;
        break;
    case Mode::LinearMeter:
        shown.value = shaft * kPi * m_settings.diameterMeter / kMmPerMeter;
        break;
    case Mode::Time: {
        // Distance per minute of the roller (in the distance unit), then the time for the
        // whole distance.
        const double perMinute = std::abs(shaft) * kPi * m_settings.timeDiameter /
                                 (m_settings.distanceInYards ? kMmPerYard : kMmPerMeter);
        if (!(perMinute > 0) || !(m_settings.distance > 0)) {
            shown.text = m_settings.timeInSeconds ? QStringLiteral("--") : QStringLiteral("--:--");
            shown.panel = shown.text;
            return shown;
        }
        const double minutes = m_settings.distance / perMinute;
        shown.valid = true;
        if (m_settings.timeInSeconds) {
            shown.value = minutes * 60;
            shown.text = ValueCodec::formatNumber(shown.value, decimals);
            shown.panel = panelText(shown.text, &shown.overflow);
            return shown;
        }
        shown.value = minutes;
        const qint64 seconds = std::llround(minutes * 60);
        shown.text =
            QStringLiteral("%1:%2").arg(seconds / 60).arg(seconds % 60, 2, 10, QLatin1Char('0'));
        shown.panel = shown.text;
        return shown;
    }
    }
    shown.valid = std::isfinite(shown.value);
    if (shown.value == 0)
        shown.value = 0; // no "-0"
    shown.text = ValueCodec::formatNumber(shown.value, decimals);
    shown.panel = panelText(shown.text, &shown.overflow);
    return shown;
}

QString SpeedDisplay::panelText(const QString& text, bool* overflow)
{
    const auto digits = [](const QString& t) {
        int n = 0;
        for (QChar c : t)
            n += c == QLatin1Char('.') ? 0 : 1;
        return n;
    };
    QString t = text;
    while (digits(t) > kPanelDigits && t.contains(QLatin1Char('.'))) {
        t.chop(1);
        if (t.endsWith(QLatin1Char('.')))
            t.chop(1);
    }
    if (overflow)
        *overflow = digits(t) > kPanelDigits;
    return t;
}

} // namespace opentop
