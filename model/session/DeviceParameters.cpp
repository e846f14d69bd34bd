#include "model/session/DeviceParameters.h"

#include "model/profile/ValueCodec.h"
#include "model/profile/WriteOrder.h"
#include "model/session/DeviceSession.h"
#include "model/session/SettingCheck.h"

#include <algorithm>

namespace opentop {

struct DeviceParameters::WriteState
{
    QStringList queue;
    int failed = 0;
    std::function<void(int)> done;
};

DeviceParameters::DeviceParameters(DeviceSession* session, QObject* parent)
    : QObject(parent)
    , m_session(session)
{
    for (const ParameterMeta& m : session->profile().parameters) {
        if (m.kind == QLatin1String("reserved"))
            continue;
        Entry e;
        e.meta = &m;
        m_entries.insert(m.name, e);
    }
    // Values the session reads for anyone (a monitor, another page) are device values too.
    connect(session, &DeviceSession::valueUpdated, this,
            [this](const QString& name, const ParamValue& value) {
                auto it = m_entries.find(name);
                if (it == m_entries.end())
                    return;
                it->device = value;
                if (it->state == State::Unread || it->state == State::Clean) {
                    it->state = State::Clean;
                    it->message.clear(); // an earlier read failure is over
                }
                emit entryChanged(name);
            });
}

const Profile& DeviceParameters::profile() const
{
    return m_session->profile();
}

const DeviceParameters::Entry* DeviceParameters::entry(const QString& name) const
{
    const auto it = m_entries.constFind(name);
    return it == m_entries.cend() ? nullptr : &it.value();
}

void DeviceParameters::refresh(const QStringList& names, std::function<void(int failed)> done)
{
    QStringList wanted = names;
    if (wanted.isEmpty()) {
        for (const ParameterMeta& m : profile().parameters) {
            if (m.isReadable() && m_entries.contains(m.name))
                wanted << m.name;
        }
    }
    m_session->readMany(wanted, [this, done](const DeviceSession::ReadManyOutcome& o) {
        for (const QString& name : o.order) {
            const DeviceSession::Outcome r = o.results.value(name);
            auto it = m_entries.find(name);
            if (it == m_entries.end() || r.ok)
                continue; // successful reads arrived through valueUpdated
            it->message = r.error;
            emit entryChanged(name);
        }
        if (done)
            done(o.failed);
    });
}

void DeviceParameters::recheck()
{
    for (const QString& name : pendingNames()) {
        const Entry& e = m_entries[name];
        if (e.state == State::Pending || e.state == State::Invalid)
            setPending(name, e.pendingText);
    }
}

QString DeviceParameters::setPending(const QString& name, const QString& text)
{
    auto it = m_entries.find(name);
    if (it == m_entries.end())
        return tr("%1 has no parameter \"%2\"").arg(profile().family, name);
    if (!it->meta->isWritable())
        return tr("%1 is read-only").arg(it->meta->label);
    if (!it->meta->safety.isEmpty())
        return tr("%1 is a command, not a setting; commands are sent one by one on request")
            .arg(it->meta->label);
    // Validate against what the drive will hold once the other pending edits are written.
    const ValueContext context = SettingCheck::overlay(
        m_session->context(), [this](const QString& other) -> std::optional<qint64> {
            const auto e = m_entries.constFind(other);
            if (e != m_entries.cend() && e->state == State::Pending &&
                !e->pendingRegisters.isEmpty())
                return qint64(ValueCodec::registersToRaw(*e->meta, e->pendingRegisters));
            return std::nullopt;
        });
    // The serial lock and the dependent settings are asked about and checked when written.
    const SettingCheck encoded =
        SettingCheck::of(profile(), *it->meta, text, context, pendingNames());
    if (!encoded.ok) {
        // Kept as typed, so the field shows it, Revert undoes it and no write goes around it.
        it->pendingText = text.trimmed();
        it->pendingRegisters.clear();
        it->state = State::Invalid;
        it->message = encoded.error;
        emit entryChanged(name);
        return encoded.error;
    }
    if (it->device.valid && encoded.registers == it->device.registers) {
        revert(name); // typing the device's own value back is no edit
        return QString();
    }
    // The drives that execute this drive's writes too (a group's children) must allow it.
    if (const QString refused = m_session->reachedProblem(name, encoded.registers);
        !refused.isEmpty()) {
        it->pendingText = text.trimmed();
        it->pendingRegisters.clear();
        it->state = State::Invalid;
        it->message = refused;
        emit entryChanged(name);
        return refused;
    }
    it->pendingText = text.trimmed();
    it->pendingRegisters = encoded.registers;
    it->state = State::Pending;
    it->message.clear();
    it->notVerified.clear();
    emit entryChanged(name);
    // Edits whose allowed values depend on this one are checked again: they may become invalid,
    // or valid again.
    for (auto other = m_entries.begin(); other != m_entries.end(); ++other) {
        if ((other->state == State::Pending || other->state == State::Invalid) &&
            other->meta->controllingParameters().contains(name)) {
            const ValueCodec::Encoded again =
                ValueCodec::encodeText(*other->meta, other->pendingText, context);
            other->message = again.ok ? QString() : again.error;
            other->pendingRegisters = again.ok ? again.registers : QVector<quint16>();
            other->state = again.ok ? State::Pending : State::Invalid;
            emit entryChanged(other.key());
        }
    }
    return QString();
}

void DeviceParameters::revert(const QString& name)
{
    auto it = m_entries.find(name);
    if (it == m_entries.end())
        return;
    it->pendingText.clear();
    it->pendingRegisters.clear();
    it->message.clear();
    it->notVerified.clear();
    it->state = it->device.valid ? State::Clean : State::Unread;
    emit entryChanged(name);
}

void DeviceParameters::revertAll()
{
    for (const QString& name : pendingNames())
        revert(name);
}

QStringList DeviceParameters::pendingNames(const QString& group) const
{
    QStringList names;
    for (const ParameterMeta& m : profile().parameters) {
        const auto it = m_entries.constFind(m.name);
        if (it != m_entries.cend() &&
            (it->state == State::Pending || it->state == State::Invalid ||
             (it->state == State::Failed && !it->pendingText.isEmpty())) &&
            (group.isEmpty() || m.group == group))
            names << m.name;
    }
    return names;
}

bool DeviceParameters::hasPending() const
{
    for (const Entry& e : m_entries) {
        if (e.state == State::Pending || e.state == State::Writing || e.state == State::Invalid ||
            (e.state == State::Failed && !e.pendingText.isEmpty()))
            return true;
    }
    return false;
}

QStringList DeviceParameters::invalidNames(const QStringList& names) const
{
    QStringList invalid;
    for (const ParameterMeta& m : profile().parameters) {
        const auto it = m_entries.constFind(m.name);
        if (it != m_entries.cend() && it->state == State::Invalid &&
            (names.isEmpty() || names.contains(m.name)))
            invalid << m.name;
    }
    return invalid;
}

QString DeviceParameters::problemText(const QString& name) const
{
    const Entry* e = entry(name);
    return e ? withoutName(name, e->message) : QString();
}

QString DeviceParameters::warningText(const QString& name) const
{
    const Entry* e = entry(name);
    if (!e || !e->meta->isNumeric())
        return QString();
    const ValueContext context = m_session->context();
    if (e->state == State::Pending && !e->pendingRegisters.isEmpty())
        return withoutName(
            name,
            ValueCodec::recommendationWarning(
                *e->meta, ValueCodec::registersToRaw(*e->meta, e->pendingRegisters), context));
    if (e->state == State::Invalid || !e->device.valid)
        return QString();
    return withoutName(name, ValueCodec::recommendationWarning(*e->meta, e->device.raw, context));
}

QString DeviceParameters::withoutName(const QString& name, const QString& message) const
{
    const Entry* e = entry(name);
    if (!e)
        return message;
    // Messages start with the parameter's name as the session names it ("SPno2 speed: …").
    QString text = message;
    for (const QString& prefix : {m_session->nameFor(name), name, e->meta->label}) {
        if (text.startsWith(prefix + QStringLiteral(": "))) {
            text = text.mid(prefix.size() + 2);
            break;
        }
    }
    return text;
}

QStringList DeviceParameters::invalidSummary(const QStringList& names) const
{
    QStringList lines;
    for (const QString& n : invalidNames(names))
        lines << tr("%1: %2").arg(entry(n)->meta->label, problemText(n));
    return lines;
}

QStringList DeviceParameters::failedSummary(const QStringList& names) const
{
    QStringList lines;
    for (const ParameterMeta& m : profile().parameters) {
        const auto it = m_entries.constFind(m.name);
        if (it != m_entries.cend() && it->state == State::Failed && !it->message.isEmpty() &&
            (names.isEmpty() || names.contains(m.name)))
            lines << tr("%1: %2").arg(m.label, problemText(m.name));
    }
    return lines;
}

QStringList DeviceParameters::notVerifiedSummary(const QStringList& names) const
{
    QStringList lines;
    for (const ParameterMeta& m : profile().parameters) {
        const auto it = m_entries.constFind(m.name);
        if (it != m_entries.cend() && !it->notVerified.isEmpty() &&
            (names.isEmpty() || names.contains(m.name)))
            lines << tr("%1: %2").arg(m.label, it->notVerified);
    }
    return lines;
}

QString DeviceParameters::writeResultText(const QStringList& names, int failed, bool* problem) const
{
    const QStringList unverified = notVerifiedSummary(names);
    *problem = failed > 0 || !unverified.isEmpty();
    QStringList lines;
    if (failed > 0)
        lines << tr("%n write(s) failed: %1", nullptr, failed)
                     .arg(failedSummary(names).join(QLatin1Char(' ')));
    if (!unverified.isEmpty())
        lines << tr("Written, but not verified on every drive it reached: %1")
                     .arg(unverified.join(QLatin1Char(' ')));
    if (lines.isEmpty())
        return tr("%n value(s) written and verified", nullptr, int(names.size()));
    return lines.join(QLatin1Char('\n'));
}

void DeviceParameters::write(const QStringList& names, std::function<void(int failed)> done)
{
    auto state = std::make_shared<WriteState>();
    state->done = std::move(done);
    const QStringList pending = pendingNames();
    QStringList wanted;
    for (const QString& n : names.isEmpty() ? pending : names) {
        if (pending.contains(n))
            wanted << n;
    }
    const QStringList invalid = invalidNames(wanted);
    if (!invalid.isEmpty()) { // all or nothing: a page is not written with a field left out
        if (state->done)
            state->done(int(invalid.size()));
        return;
    }
    state->queue = WriteOrder::of(profile(), wanted);
    for (const QString& n : state->queue) {
        m_entries[n].state = State::Writing;
        emit entryChanged(n);
    }
    writeNext(state);
}

void DeviceParameters::writeNext(std::shared_ptr<WriteState> state)
{
    if (state->queue.isEmpty()) {
        if (state->done)
            state->done(state->failed);
        return;
    }
    const QString name = state->queue.takeFirst();
    DeviceSession::WriteOptions options; // settings only: commands are never pending edits
    options.companions = state->queue;   // written next, in dependency order
    m_session->write(name, m_entries.value(name).pendingText, options,
                     [this, name, state](const DeviceSession::Outcome& o) {
                         Entry& e = m_entries[name];
                         e.notVerified = o.ok ? o.notVerified : QString();
                         if (o.ok) {
                             e.pendingText.clear();
                             e.pendingRegisters.clear();
                             e.message.clear();
                             e.state = State::Clean;
                             if (o.value.valid)
                                 e.device = o.value;
                         } else {
                             e.state = State::Failed;
                             // What a device's error code means goes with it.
                             e.message = o.explanation.isEmpty()
                                             ? o.error
                                             : o.error + QLatin1Char('\n') + o.explanation;
                             ++state->failed;
                         }
                         emit entryChanged(name);
                         writeNext(state);
                     });
}

QString DeviceParameters::deviceText(const QString& name) const
{
    const Entry* e = entry(name);
    if (!e || !e->device.valid)
        return QString();
    return ValueCodec::format(*e->meta, e->device, m_session->context());
}

QString DeviceParameters::allowedText(const QString& name) const
{
    const Entry* e = entry(name);
    return e ? ValueCodec::allowedText(*e->meta, m_session->context()) : QString();
}

} // namespace opentop
