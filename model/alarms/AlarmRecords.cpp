#include "model/alarms/AlarmRecords.h"

#include "model/profile/ParamValue.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

namespace opentop {

namespace {

const QString kAlarm = QStringLiteral("alarm");
const QString kWarning = QStringLiteral("warning");
const QString kCommError = QStringLiteral("comm_error");
const QString kAlarmActive = QStringLiteral("alarmActive");

} // namespace

int AlarmRecords::History::used() const
{
    int n = 0;
    for (const Record& r : records)
        n += r.empty ? 0 : 1;
    return n;
}

QVector<CodeEntry> AlarmRecords::History::distinctEntries() const
{
    QVector<CodeEntry> result;
    for (const Record& r : records) {
        if (!r.entry)
            continue;
        bool seen = false;
        for (const CodeEntry& e : result)
            seen = seen || e.code == r.entry->code;
        if (!seen)
            result << *r.entry;
    }
    return result;
}

AlarmRecords::AlarmRecords(const DeviceSession* session)
    : m_session(session)
{
}

QVector<const ParameterMeta*> AlarmRecords::recordParameters() const
{
    return m_session->profile().records(kAlarm) + m_session->profile().records(kWarning);
}

const ParameterMeta* AlarmRecords::commErrorMeta() const
{
    for (const ParameterMeta& p : m_session->profile().parameters) {
        if (p.codeTable == kCommError && p.isReadable() && p.kind != QLatin1String("record"))
            return &p;
    }
    return nullptr;
}

AlarmRecords::Report AlarmRecords::decode(const QHash<QString, double>& raw,
                                          const QHash<QString, QString>& errors) const
{
    const Profile& profile = m_session->profile();
    Report report;
    for (const QString& table : {kAlarm, kWarning}) {
        const QVector<const ParameterMeta*> metas = profile.records(table);
        if (metas.isEmpty())
            continue;
        const CodeTable* codes = profile.codeTable(table);
        History h;
        h.table = table;
        h.label = codes ? codes->label : table;
        h.ok = true;
        for (int i = 0; i < metas.size(); ++i) {
            Record r;
            r.index = i + 1;
            if (!raw.contains(metas[i]->name)) {
                h.ok = false;
                h.error = errors.value(metas[i]->name);
            } else {
                r.code = qint64(raw.value(metas[i]->name));
                r.empty = r.code == 0;
                if (const CodeEntry* e = codes && !r.empty ? codes->find(r.code) : nullptr)
                    r.entry = *e;
            }
            h.records << r;
        }
        if (!h.ok)
            report.errors << tr("%1: %2").arg(h.label, h.error);
        report.histories << h;
    }
    if (const ParameterMeta* meta = commErrorMeta()) {
        report.commErrorParameter = meta->name;
        if (raw.contains(meta->name)) {
            report.commErrorCode = qint64(raw.value(meta->name));
            const CodeTable* codes = profile.codeTable(kCommError);
            if (const CodeEntry* e = codes ? codes->find(*report.commErrorCode) : nullptr)
                report.commError = *e;
        } else {
            report.errors << tr("%1: %2").arg(meta->label, errors.value(meta->name));
        }
    }
    report.alarmActive = RoleEvaluator::flag(profile, kAlarmActive, [&raw](const QString& n) {
        return raw.contains(n) ? std::optional<double>(raw.value(n)) : std::nullopt;
    });
    const ParameterMeta* method = profile.parameter(eraseMethodParameter());
    if (method && raw.contains(method->name)) {
        const double code = raw.value(method->name);
        report.powerRestartOnly = eraseMethodIsPower(code);
        ParamValue v;
        v.valid = true;
        v.raw = code;
        v.number = code;
        report.eraseMethod = QStringLiteral("%1 = %2").arg(
            method->name, ValueCodec::format(*method, v, m_session->context()));
    }
    report.ok = report.errors.isEmpty();
    return report;
}

QString AlarmRecords::eraseMethodParameter() const
{
    const ProfileRole* role = m_session->profile().role(QStringLiteral("alarmEraseByPower"));
    return role ? role->parameter : QString();
}

bool AlarmRecords::eraseMethodIsPower(double raw) const
{
    const ProfileRole* role = m_session->profile().role(QStringLiteral("alarmEraseByPower"));
    return role && role->value && qint64(raw) == *role->value;
}

QStringList AlarmRecords::parametersToRead() const
{
    QStringList names;
    for (const ParameterMeta* meta : recordParameters())
        names << meta->name;
    if (const ParameterMeta* meta = commErrorMeta())
        names << meta->name;
    const ParameterMeta* active = RoleEvaluator::parameter(m_session->profile(), kAlarmActive);
    if (active && active->isReadable() && !names.contains(active->name))
        names << active->name;
    const ParameterMeta* method = m_session->profile().parameter(eraseMethodParameter());
    if (method && method->isReadable())
        names << method->name;
    return names;
}

} // namespace opentop
