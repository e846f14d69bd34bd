#include "cli/MonitorOutput.h"

#include "cli/TerminalWidth.h"

#include "model/io/DisplayText.h"
#include "model/monitor/DeviceMonitor.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::MonitorOutput", text);
}

constexpr int kShortHeader = 21; // longer labels give way to the parameter's name

QString shortHeader(QString label, const QString& name)
{
    const int paren = int(label.indexOf(QStringLiteral(" (")));
    if (paren > 0)
        label.truncate(paren); // "Selected running data (M bits)"
    return label.size() <= kShortHeader ? label : name.section(QLatin1Char('.'), -1);
}

// How wide a value of `meta` can get as text, so that consecutive lines align.
int valueWidth(const ParameterMeta& meta, const ValueContext& context)
{
    const ValueSpec& spec = meta.specFor(context);
    int width = 0;
    for (const EnumOption& o : spec.options)
        width = std::max(width, TerminalWidth::of(o.label));
    if (!spec.ranges.isEmpty() || spec.options.isEmpty()) {
        int digits = 5 + (spec.decimals > 0 ? spec.decimals + 1 : 0);
        for (const ValueRange& r : spec.ranges) {
            for (double raw : {r.min, r.max})
                digits = std::max<int>(
                    digits, ValueCodec::formatNumber(raw * spec.scale, spec.decimals).size());
        }
        width =
            std::max(width, digits + (spec.unit.isEmpty() ? 0 : TerminalWidth::of(spec.unit) + 1));
    }
    return width;
}

QJsonValue number(double value)
{
    return value == std::floor(value) && std::abs(value) < 1e15 ? QJsonValue(qint64(value))
                                                                : QJsonValue(value);
}

QJsonObject shownJson(const SpeedDisplay::Shown& shown)
{
    QJsonObject o{{QStringLiteral("text"), shown.text}, {QStringLiteral("unit"), shown.unit}};
    o.insert(QStringLiteral("value"), shown.valid ? number(shown.value) : QJsonValue());
    return o;
}

} // namespace

MonitorOutput::MonitorOutput(const DeviceMonitor& monitor)
    : m_monitor(monitor)
{
    const DeviceSession& session = *monitor.session();
    const Profile& profile = session.profile();
    const ValueContext context = session.context();
    m_family = profile.family;
    const ProfileRole* alarmRole = profile.role(QStringLiteral("alarmActive"));
    const ParameterMeta* current =
        RoleEvaluator::parameter(profile, QStringLiteral("currentSpeed"));
    const ParameterMeta* target = RoleEvaluator::parameter(profile, QStringLiteral("targetSpeed"));
    for (const QString& name : monitor.parameters()) {
        const ParameterMeta* meta = profile.parameter(name);
        if (!meta)
            continue;
        if (meta->type == DataType::Bits && !meta->bits.isEmpty()) {
            for (const BitField& f : meta->bits) {
                // The alarm flag is shown with its name in the alarm column.
                if (alarmRole && alarmRole->parameter == name && alarmRole->field == f.name)
                    continue;
                Column c;
                c.kind = Column::Kind::Field;
                c.parameter = name;
                c.field = f.name;
                c.header = shortHeader(f.label, f.name);
                c.key = name + QLatin1Char('.') + f.name;
                for (const QString& v : f.values)
                    c.width = std::max(c.width, TerminalWidth::of(v));
                c.width = std::max({c.width, TerminalWidth::of(c.header), 2});
                m_columns << c;
            }
            continue;
        }
        const ValueSpec& spec = meta->specFor(context);
        Column c;
        c.parameter = name;
        c.header = shortHeader(meta->label, name);
        c.number = meta->isNumeric() && spec.options.isEmpty();
        c.key = spec.unit.isEmpty() || !c.number ? name
                                                 : QStringLiteral("%1 [%2]").arg(name, spec.unit);
        c.width = std::max(TerminalWidth::of(c.header), valueWidth(*meta, context));
        m_columns << c;
        const std::optional<SpeedDisplay>& display = monitor.speedDisplay();
        if (display && (meta == current || meta == target)) {
            Column d;
            d.kind = Column::Kind::Display;
            d.parameter = name;
            d.target = meta == target;
            d.number = true;
            d.header = d.target ? tr("Target shown") : tr("Speed shown");
            d.key = QStringLiteral("%1.display [%2]").arg(name, display->unit());
            d.width =
                std::max(TerminalWidth::of(d.header), 10 + TerminalWidth::of(display->unit()));
            m_columns << d;
        }
    }
    if (alarmRole) {
        Column a;
        a.kind = Column::Kind::Alarm;
        a.header = tr("Active alarm");
        a.key = QStringLiteral("alarm");
        a.width = TerminalWidth::of(a.header);
        m_columns << a;
    }
}

QString MonitorOutput::timeText(const MonitorSample& sample)
{
    return sample.timestamp.toString(QStringLiteral("HH:mm:ss.zzz"));
}

QString MonitorOutput::isoTime(const QDateTime& time)
{
    return time.toOffsetFromUtc(time.offsetFromUtc()).toString(Qt::ISODateWithMs);
}

QString MonitorOutput::text(const Column& c, const MonitorSample& s) const
{
    switch (c.kind) {
    case Column::Kind::Value: {
        const MonitorValue* v = s.find(c.parameter);
        return v ? v->text : QString();
    }
    case Column::Kind::Field: {
        const MonitorValue* v = s.find(c.parameter);
        const BitField* f = v && v->meta ? RoleEvaluator::bitField(*v->meta, c.field) : nullptr;
        return f && v->value.valid
                   ? RoleEvaluator::fieldText(*f, RoleEvaluator::fieldValue(*f, v->value.raw))
                   : QString();
    }
    case Column::Kind::Display: {
        const std::optional<SpeedDisplay::Shown>& shown = c.target ? s.targetShown : s.currentShown;
        if (!shown)
            return QString();
        return shown->unit == QLatin1String("min:s") ? shown->text
                                                     : shown->text + QLatin1Char(' ') + shown->unit;
    }
    case Column::Kind::Alarm:
        if (!s.alarmActive)
            return QString();
        if (!*s.alarmActive)
            return tr("none");
        if (s.activeAlarm)
            return s.activeAlarm->panel + QLatin1Char(' ') + s.activeAlarm->name;
        return s.activeAlarmCode ? tr("code %1").arg(*s.activeAlarmCode) : tr("active");
    }
    return QString();
}

QString MonitorOutput::headerLine() const
{
    QString line = TerminalWidth::padRight(tr("Time"), 12) + QStringLiteral("  ") +
                   TerminalWidth::padLeft(tr("ID"), 3);
    for (const Column& c : m_columns)
        line += QStringLiteral("  ") + (c.number ? TerminalWidth::padLeft(c.header, c.width)
                                                 : TerminalWidth::padRight(c.header, c.width));
    return line.trimmed();
}

QString MonitorOutput::line(const MonitorSample& sample) const
{
    QString line =
        timeText(sample) + QStringLiteral("  ") + QString::number(sample.slave).rightJustified(3);
    for (const Column& c : m_columns) {
        const QString cell = text(c, sample);
        line += QStringLiteral("  ") + (c.number ? TerminalWidth::padLeft(cell, c.width)
                                                 : TerminalWidth::padRight(cell, c.width));
    }
    while (line.endsWith(QLatin1Char(' ')))
        line.chop(1);
    return line;
}

QStringList MonitorOutput::csvCells(const MonitorSample& sample) const
{
    QStringList cells;
    for (const Column& c : m_columns) {
        if (c.kind == Column::Kind::Value && c.number) {
            const MonitorValue* v = sample.find(c.parameter);
            const ValueSpec& spec =
                v && v->meta ? v->meta->specFor(m_monitor.session()->context()) : ValueSpec();
            cells << (v && v->value.valid ? ValueCodec::formatNumber(v->value.number, spec.decimals)
                                          : QString());
        } else if (c.kind == Column::Kind::Display) {
            const auto& shown = c.target ? sample.targetShown : sample.currentShown;
            cells << (shown && shown->valid ? shown->text : QString());
        } else if (c.kind == Column::Kind::Alarm) {
            cells << (sample.activeAlarm ? sample.activeAlarm->panel : text(c, sample));
        } else {
            cells << text(c, sample);
        }
    }
    return cells;
}

QString MonitorOutput::csvEscape(const QString& text)
{
    // No control character, and no text a spreadsheet would compute (DisplayText::csvCell).
    const QString cell = DisplayText::csvCell(text);
    if (!cell.contains(QLatin1Char(',')) && !cell.contains(QLatin1Char('"')))
        return cell;
    QString quoted = cell;
    quoted.replace(QStringLiteral("\""), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QJsonObject MonitorOutput::json(const MonitorSample& sample) const
{
    const ValueContext context = m_monitor.session()->context();
    QJsonObject values;
    for (const MonitorValue& v : sample.values) {
        if (!v.meta)
            continue;
        QJsonObject o;
        if (!v.value.valid) {
            o.insert(QStringLiteral("error"), v.value.error);
        } else if (v.meta->type == DataType::Bits) {
            QJsonObject fields;
            for (const BitField& f : v.meta->bits)
                fields.insert(
                    f.name, RoleEvaluator::fieldText(f, RoleEvaluator::fieldValue(f, v.value.raw)));
            o.insert(QStringLiteral("raw"), number(v.value.raw));
            o.insert(QStringLiteral("fields"), fields);
        } else {
            o.insert(QStringLiteral("value"), number(v.value.number));
            o.insert(QStringLiteral("text"), v.text);
            const QString unit = v.meta->specFor(context).unit;
            if (!unit.isEmpty())
                o.insert(QStringLiteral("unit"), unit);
        }
        values.insert(v.meta->name, o);
    }
    QJsonObject root{
        {QStringLiteral("timestamp"), isoTime(sample.timestamp)},
        {QStringLiteral("slave"), sample.slave},
        {QStringLiteral("family"), m_family},
        {QStringLiteral("values"), values},
    };
    if (sample.running)
        root.insert(QStringLiteral("running"), *sample.running);
    if (sample.alarmActive)
        root.insert(QStringLiteral("alarmActive"), *sample.alarmActive);
    if (sample.activeAlarm)
        root.insert(QStringLiteral("alarm"),
                    QJsonObject{{QStringLiteral("code"), sample.activeAlarm->code},
                                {QStringLiteral("panel"), sample.activeAlarm->panel},
                                {QStringLiteral("name"), sample.activeAlarm->name}});
    QJsonObject display;
    if (sample.currentShown)
        display.insert(QStringLiteral("currentSpeed"), shownJson(*sample.currentShown));
    if (sample.targetShown)
        display.insert(QStringLiteral("targetSpeed"), shownJson(*sample.targetShown));
    if (!display.isEmpty())
        root.insert(QStringLiteral("display"), display);
    return root;
}

} // namespace opentop
