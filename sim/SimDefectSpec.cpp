#include "sim/SimDefectSpec.h"

#include <QRegularExpression>
#include <cmath>

namespace opentop {

namespace {

constexpr qint64 kMaxAlarmDelayMs = 3600000;
constexpr int kMaxSpeed = 10000;

QString number(double value)
{
    return QString::number(value, 'g', 6);
}

// "1500ms", "1.5s", "1500" (ms); nothing when malformed or out of 0..1 h.
std::optional<qint64> parseDelay(const QString& text)
{
    static const QRegularExpression form(QStringLiteral("^(\\d+(?:\\.\\d+)?)(ms|s)?$"),
                                         QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch m = form.match(text.trimmed());
    if (!m.hasMatch())
        return std::nullopt;
    const double value = m.captured(1).toDouble();
    const double ms =
        m.captured(2).compare(QLatin1String("s"), Qt::CaseInsensitive) == 0 ? value * 1000 : value;
    if (ms > kMaxAlarmDelayMs || ms != std::floor(ms))
        return std::nullopt;
    return qint64(ms);
}

bool isParameterText(const QString& text)
{
    static const QRegularExpression form(
        QStringLiteral("^(?:[A-Za-z][A-Za-z0-9_.]*|0x[0-9A-Fa-f]{1,4}|[0-9A-Fa-f]{1,4}h|\\d+)$"));
    return form.match(text).hasMatch();
}

} // namespace

QString SimDefectSpec::forms()
{
    return tr("firmware=MAJOR.MINOR (e.g. firmware=1.4), max_speed=N (e.g. max_speed=800), "
              "stall, load=+N, load=-N or load=xF (e.g. load=+40, load=x1.5), "
              "alarm=CODE@TIME (e.g. alarm=0x07@1500ms, alarm=overload@2s; DC: alarm=stall@1s), "
              "nostick=PARAM, nostore=PARAM (a parameter name or register address, e.g. "
              "nostick=spno2.speed, nostore=0x0081), turnaround=MS (e.g. turnaround=14), clear");
}

bool SimDefectSpec::isEmpty() const
{
    return !firmware && !maxSpeed && !stall && !loadOffset && !loadScale && alarm.isEmpty() &&
           noStick.isEmpty() && noStore.isEmpty() && !turnaroundMs;
}

QString SimDefectSpec::toString() const
{
    QStringList items;
    if (firmware)
        items << QStringLiteral("firmware=%1.%2").arg(*firmware >> 8).arg(*firmware & 0xFF);
    if (maxSpeed)
        items << QStringLiteral("max_speed=%1").arg(*maxSpeed);
    if (stall)
        items << QStringLiteral("stall");
    if (loadOffset)
        items << QStringLiteral("load=%1%2")
                     .arg(*loadOffset < 0 ? QString() : QStringLiteral("+"), number(*loadOffset));
    if (loadScale)
        items << QStringLiteral("load=x%1").arg(number(*loadScale));
    if (!alarm.isEmpty())
        items << QStringLiteral("alarm=%1@%2ms").arg(alarm).arg(alarmAfterMs);
    for (const QString& p : noStick)
        items << QStringLiteral("nostick=%1").arg(p);
    for (const QString& p : noStore)
        items << QStringLiteral("nostore=%1").arg(p);
    if (turnaroundMs)
        items << QStringLiteral("turnaround=%1").arg(number(*turnaroundMs));
    return items.join(QLatin1Char(','));
}

SimDefectSpec SimDefectSpec::merged(const SimDefectSpec& later) const
{
    SimDefectSpec m = later.clear ? SimDefectSpec() : *this;
    m.clear = clear || later.clear;
    if (later.firmware)
        m.firmware = later.firmware;
    if (later.maxSpeed)
        m.maxSpeed = later.maxSpeed;
    m.stall = m.stall || later.stall;
    if (later.loadOffset)
        m.loadOffset = later.loadOffset;
    if (later.loadScale)
        m.loadScale = later.loadScale;
    if (!later.alarm.isEmpty()) {
        m.alarm = later.alarm;
        m.alarmAfterMs = later.alarmAfterMs;
    }
    for (const QString& p : later.noStick) {
        if (!m.noStick.contains(p))
            m.noStick << p;
    }
    for (const QString& p : later.noStore) {
        if (!m.noStore.contains(p))
            m.noStore << p;
    }
    if (later.turnaroundMs)
        m.turnaroundMs = later.turnaroundMs;
    return m;
}

QString SimDefectSpec::parseItem(const QString& item, SimDefectSpec* spec)
{
    const int eq = item.indexOf(QLatin1Char('='));
    const QString key = (eq < 0 ? item : item.left(eq)).trimmed().toLower();
    const QString value = eq < 0 ? QString() : item.mid(eq + 1).trimmed();
    static const QStringList keys = {
        QStringLiteral("firmware"), QStringLiteral("max_speed"),  QStringLiteral("stall"),
        QStringLiteral("load"),     QStringLiteral("alarm"),      QStringLiteral("nostick"),
        QStringLiteral("nostore"),  QStringLiteral("turnaround"), QStringLiteral("clear")};
    if (!keys.contains(key))
        return tr("unknown defect \"%1\"; allowed: %2").arg(item, forms());
    const bool needsValue = key != QLatin1String("stall") && key != QLatin1String("clear");
    if (needsValue && (eq < 0 || value.isEmpty()))
        return tr("\"%1\" needs a value: %2=...").arg(item, key);
    if (!needsValue && eq >= 0)
        return tr("\"%1\" takes no value; write %2").arg(item, key);

    if (key == QLatin1String("clear")) {
        *spec = SimDefectSpec();
        spec->clear = true;
    } else if (key == QLatin1String("stall")) {
        spec->stall = true;
    } else if (key == QLatin1String("firmware")) {
        static const QRegularExpression form(QStringLiteral("^[vV]?(\\d{1,3})\\.(\\d{1,3})$"));
        const QRegularExpressionMatch m = form.match(value);
        const int major = m.captured(1).toInt();
        const int minor = m.captured(2).toInt();
        if (!m.hasMatch() || major > 255 || minor > 255)
            return tr("firmware=%1: write MAJOR.MINOR with each 0..255, e.g. firmware=1.4")
                .arg(value);
        spec->firmware = (major << 8) | minor;
    } else if (key == QLatin1String("max_speed")) {
        bool ok = false;
        const int speed = value.toInt(&ok);
        if (!ok || speed < 0 || speed > kMaxSpeed)
            return tr("max_speed=%1: write a whole number 0..%2, e.g. max_speed=800")
                .arg(value)
                .arg(kMaxSpeed);
        spec->maxSpeed = speed;
    } else if (key == QLatin1String("load")) {
        bool ok = false;
        const QChar first = value.at(0);
        if (first == QLatin1Char('x') || first == QLatin1Char('*')) {
            const double scale = value.mid(1).toDouble(&ok);
            if (!ok || scale < 0.1 || scale > 10)
                return tr("load=%1: a factor is x0.1..x10, e.g. load=x1.5").arg(value);
            spec->loadScale = scale;
        } else if (first == QLatin1Char('+') || first == QLatin1Char('-')) {
            const double offset = value.toDouble(&ok);
            if (!ok || offset < -200 || offset > 200)
                return tr("load=%1: an offset is -200..+200, e.g. load=+40").arg(value);
            spec->loadOffset = offset;
        } else {
            return tr("load=%1: write load=+N, load=-N (an offset) or load=xF (a factor), e.g. "
                      "load=+40 or load=x1.5")
                .arg(value);
        }
    } else if (key == QLatin1String("alarm")) {
        const int at = value.indexOf(QLatin1Char('@'));
        const QString code = at < 0 ? value : value.left(at).trimmed();
        static const QRegularExpression codeForm(QStringLiteral("^[A-Za-z0-9_-]+$"));
        if (at < 0 || code.isEmpty() || !codeForm.match(code).hasMatch())
            return tr("alarm=%1: write alarm=CODE@TIME, e.g. alarm=0x07@1500ms or "
                      "alarm=overload@2s")
                .arg(value);
        const std::optional<qint64> delay = parseDelay(value.mid(at + 1));
        if (!delay)
            return tr("alarm=%1: the time after the start is 0..3600 s, written 1500ms, 1.5s or "
                      "1500 (ms)")
                .arg(value);
        spec->alarm = code.toLower();
        spec->alarmAfterMs = *delay;
    } else if (key == QLatin1String("turnaround")) {
        bool ok = false;
        const double ms = value.toDouble(&ok);
        if (!ok || ms < 0 || ms > 1000)
            return tr("turnaround=%1: write the answer delay in ms, 0..1000, e.g. turnaround=14")
                .arg(value);
        spec->turnaroundMs = ms;
    } else if (key == QLatin1String("nostick") || key == QLatin1String("nostore")) {
        if (!isParameterText(value))
            return tr("%1=%2: name a parameter (e.g. spno2.speed) or a register address (e.g. "
                      "0x1102)")
                .arg(key, value);
        QStringList& list = key == QLatin1String("nostick") ? spec->noStick : spec->noStore;
        if (!list.contains(value))
            list << value;
    }
    return QString();
}

std::optional<SimDefectSpec> SimDefectSpec::parse(const QString& text, QString* error)
{
    SimDefectSpec spec;
    const QStringList items = text.split(QLatin1Char(','));
    if (text.trimmed().isEmpty()) {
        if (error)
            *error = tr("no defect given; allowed: %1").arg(forms());
        return std::nullopt;
    }
    for (const QString& raw : items) {
        const QString item = raw.trimmed();
        const QString why =
            item.isEmpty() ? tr("empty item in \"%1\"").arg(text) : parseItem(item, &spec);
        if (!why.isEmpty()) {
            if (error)
                *error = why;
            return std::nullopt;
        }
    }
    return spec;
}

std::optional<SimDefectSpec> SimDefectSpec::parseOption(const QString& text, int* slave,
                                                        QString* error)
{
    const int colon = text.indexOf(QLatin1Char(':'));
    bool ok = false;
    const int id = colon > 0 ? text.left(colon).trimmed().toInt(&ok) : 0;
    if (!ok || id < 1 || id > 247) {
        if (error)
            *error = tr("\"%1\": write ID:DEFECT[,DEFECT...] with ID the machine number 1..247, "
                        "e.g. 3:firmware=1.4 or 5:max_speed=800,load=+40")
                         .arg(text);
        return std::nullopt;
    }
    std::optional<SimDefectSpec> spec = parse(text.mid(colon + 1), error);
    if (spec && slave)
        *slave = id;
    return spec;
}

} // namespace opentop
