#include "session/DeviceSession.h"

#include "session/DependentValues.h"

#include "ModbusClient.h"
#include "profile/ValueCodec.h"
#include "session/ReadPlanner.h"

#include <utility>

namespace opentop {

namespace {

ModbusRequest readRequest(int slave, const ParameterMeta& meta)
{
    return meta.readFunction == 4
               ? ModbusRequest::readInput(quint8(slave), meta.address, quint16(meta.registerCount))
               : ModbusRequest::readHolding(quint8(slave), meta.address,
                                            quint16(meta.registerCount));
}

const ParameterMeta* commErrorParameter(const Profile& profile)
{
    for (const ParameterMeta& p : profile.parameters) {
        if (p.codeTable == QLatin1String("comm_error") && p.isReadable())
            return &p;
    }
    return nullptr;
}

} // namespace

DeviceSession::DeviceSession(ModbusClient* client, const Profile& profile, int slave,
                             const QString& variant, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_profile(profile)
    , m_slave(slave)
    , m_variant(variant)
{
}

ValueContext DeviceSession::context() const
{
    ValueContext c;
    c.variant = m_variant;
    if (m_variant.isEmpty()) {
        for (const ProfileVariant& v : m_profile.variants)
            c.possibleVariants << v.id;
    }
    c.parameterRaw = [this](const QString& name) -> std::optional<qint64> {
        const ParameterMeta* meta = m_profile.parameter(name);
        const auto it = m_cache.constFind(name);
        if (!meta || it == m_cache.cend())
            return std::nullopt;
        return qint64(ValueCodec::registersToRaw(*meta, it.value()));
    };
    if (m_labelsInMessages)
        c.displayName = [this](const QString& name) { return nameFor(name); };
    return c;
}

QString DeviceSession::nameFor(const QString& parameter) const
{
    const ParameterMeta* meta = m_labelsInMessages ? m_profile.parameter(parameter) : nullptr;
    return meta && !meta->label.isEmpty() ? meta->label : parameter;
}

ParamValue DeviceSession::cachedValue(const QString& name) const
{
    const ParameterMeta* meta = m_profile.parameter(name);
    if (!meta || !m_cache.contains(name))
        return {};
    return ValueCodec::decode(*meta, m_cache.value(name), context());
}

void DeviceSession::acceptRegisters(const QString& name, const QVector<quint16>& registers)
{
    const ParameterMeta* meta = m_profile.parameter(name);
    if (!meta || registers.size() != meta->registerCount)
        return;
    m_cache.insert(name, registers);
    emit valueUpdated(name, ValueCodec::decode(*meta, registers, context()));
}

const ParameterMeta* DeviceSession::lookup(const QString& name, Outcome* outcome) const
{
    outcome->parameter = name;
    const ParameterMeta* meta = m_profile.parameter(name);
    if (!meta)
        outcome->error = tr("%1 has no parameter \"%2\"").arg(m_profile.family, name);
    return meta;
}

void DeviceSession::read(const QString& name, Done done)
{
    Outcome outcome;
    const ParameterMeta* meta = lookup(name, &outcome);
    if (meta && !meta->isReadable())
        outcome.error = tr("%1 cannot be read (it is a write-only command)").arg(name);
    if (!outcome.error.isEmpty()) {
        done(outcome);
        return;
    }
    outcome.sent = true;
    m_client->submit(readRequest(m_slave, *meta), this,
                     [this, meta, outcome, done](const ModbusResult& r) mutable {
                         if (!r.ok()) {
                             explainFailure(r, outcome, done);
                             return;
                         }
                         acceptRegisters(meta->name, r.registers);
                         outcome.value = ValueCodec::decode(*meta, r.registers, context());
                         outcome.ok = outcome.value.valid;
                         outcome.error = outcome.value.error;
                         done(outcome);
                     });
}

namespace {

// Blocks of one readMany queued on the bus at a time: the next is waiting when one completes,
// so the worker goes on at once instead of waiting for this thread to hand it over. Two keep
// that true and leave room for user requests to overtake.
constexpr int kBlocksInFlight = 2;

} // namespace

struct DeviceSession::ManyState
{
    QVector<ReadBlockPlan> queue;
    int inFlight = 0;
    bool finished = false;
    ReadManyOutcome outcome;
    ManyDone done;
    ModbusRequest::Priority priority = ModbusRequest::Priority::Normal;
};

void DeviceSession::acceptIdentification(const QVector<quint16>& identifyRegisters)
{
    const IdentifyRule& rule = m_profile.identify;
    if (identifyRegisters.size() != rule.count)
        return;
    for (const ParameterMeta& p : m_profile.parameters) {
        if (p.readFunction != rule.function || p.address < rule.address ||
            p.address + p.registerCount > rule.address + rule.count)
            continue;
        acceptRegisters(p.name, identifyRegisters.mid(p.address - rule.address, p.registerCount));
    }
}

void DeviceSession::readMany(const QStringList& names, ManyDone done,
                             ModbusRequest::Priority priority)
{
    auto state = std::make_shared<ManyState>();
    state->priority = priority;
    state->done = std::move(done);
    state->outcome.order = names;
    QVector<const ParameterMeta*> metas;
    for (const QString& name : names) {
        Outcome o;
        const ParameterMeta* meta = lookup(name, &o);
        if (meta && !meta->isReadable())
            o.error = tr("%1 cannot be read (it is a write-only command)").arg(name);
        if (!o.error.isEmpty()) {
            state->outcome.results.insert(name, o);
            ++state->outcome.failed;
            continue;
        }
        metas << meta;
    }
    state->queue = ReadPlanner::plan(m_profile, metas);
    nextBlock(state);
}

void DeviceSession::nextBlock(std::shared_ptr<ManyState> state)
{
    if (state->queue.isEmpty() && state->inFlight == 0) {
        if (!std::exchange(state->finished, true))
            state->done(state->outcome);
        return;
    }
    while (state->inFlight < kBlocksInFlight && !state->queue.isEmpty())
        submitBlock(state, state->queue.takeFirst());
}

void DeviceSession::submitBlock(std::shared_ptr<ManyState> state, const ReadBlockPlan& plan)
{
    ModbusRequest request =
        plan.function == 4 ? ModbusRequest::readInput(quint8(m_slave), plan.address, plan.count)
                           : ModbusRequest::readHolding(quint8(m_slave), plan.address, plan.count);
    request.priority = state->priority;
    ++state->outcome.requests;
    ++state->inFlight;
    m_client->submit(request, this, [this, plan, state](const ModbusResult& r) {
        --state->inFlight;
        if (!r.ok() && r.error == ModbusError::Exception && plan.parameters.size() > 1) {
            // The device refuses the block: ask for each parameter on its own.
            const QVector<ReadBlockPlan> singles = ReadPlanner::singles(plan.parameters);
            for (int i = singles.size() - 1; i >= 0; --i)
                state->queue.prepend(singles[i]);
            nextBlock(state);
            return;
        }
        for (const ParameterMeta* meta : plan.parameters) {
            Outcome o;
            o.parameter = meta->name;
            o.sent = true;
            if (!r.ok()) {
                o.error = r.errorText();
                ++state->outcome.failed;
            } else {
                const QVector<quint16> regs =
                    r.registers.mid(meta->address - plan.address, meta->registerCount);
                acceptRegisters(meta->name, regs);
                o.value = ValueCodec::decode(*meta, regs, context());
                o.ok = o.value.valid;
                o.error = o.value.error;
            }
            state->outcome.results.insert(meta->name, o);
        }
        nextBlock(state);
    });
}

void DeviceSession::ensureControllingValues(const ParameterMeta& meta,
                                            std::function<void(QString)> then)
{
    for (const QString& controlling : meta.controllingParameters()) {
        if (m_cache.contains(controlling))
            continue;
        // Read what the allowed values depend on first, then try again.
        read(controlling, [this, &meta, then](const Outcome& o) {
            if (!o.ok) {
                then(tr("cannot check the value: reading %1 failed: %2")
                         .arg(nameFor(o.parameter), o.error));
                return;
            }
            ensureControllingValues(meta, then);
        });
        return;
    }
    then(QString());
}

void DeviceSession::write(const QString& name, const QString& text, const WriteOptions& options,
                          Done done)
{
    Outcome outcome;
    const ParameterMeta* meta = lookup(name, &outcome);
    if (meta && !meta->isWritable())
        outcome.error = tr("%1 is read-only").arg(nameFor(name));
    if (!outcome.error.isEmpty()) {
        done(outcome);
        return;
    }
    if (!meta->safety.isEmpty() && !options.explicitCommand) {
        outcome.error = tr("%1 is a %2 command; it is only sent when explicitly requested")
                            .arg(nameFor(name), meta->safety);
        done(outcome);
        return;
    }
    ensureControllingValues(*meta, [this, meta, text, options, outcome,
                                    done](const QString& problem) mutable {
        if (!problem.isEmpty()) {
            outcome.error = problem;
            done(outcome);
            return;
        }
        const ValueCodec::Encoded encoded = ValueCodec::encodeText(*meta, text, context());
        if (!encoded.ok) {
            outcome.error = encoded.error; // nothing is sent
            done(outcome);
            return;
        }
        outcome.warning = encoded.warning;
        // Settings that depend on this one must stay valid: know their values, then check.
        QStringList dependents = DependentValues::of(m_profile, *meta);
        for (const QString& c : options.companions)
            dependents.removeAll(c);
        const QVector<quint16> registers = encoded.registers;
        ensureCached(dependents, [this, meta, registers, options, outcome,
                                  done](const QString& readProblem) mutable {
            const qint64 raw = qint64(ValueCodec::registersToRaw(*meta, registers));
            const QString refusal =
                readProblem.isEmpty()
                    ? DependentValues::problem(m_profile, *meta, raw, context(), options.companions)
                    : tr("%1 cannot be checked: %2").arg(meta->label, readProblem);
            if (!refusal.isEmpty()) {
                outcome.error = refusal; // nothing is sent
                done(outcome);
                return;
            }
            send(meta, registers, options, outcome, done);
        });
    });
}

void DeviceSession::ensureCached(QStringList names, std::function<void(QString)> then)
{
    while (!names.isEmpty() && m_cache.contains(names.first()))
        names.removeFirst();
    if (names.isEmpty()) {
        then(QString());
        return;
    }
    const QString name = names.takeFirst();
    read(name, [this, names, then](const Outcome& o) {
        if (!o.ok && !m_cache.contains(o.parameter)) {
            then(tr("reading %1 failed: %2").arg(nameFor(o.parameter), o.error));
            return;
        }
        ensureCached(names, then);
    });
}

void DeviceSession::send(const ParameterMeta* meta, const QVector<quint16>& registers,
                         const WriteOptions& options, Outcome outcome, Done done, int busyRetries)
{
    const BlockWrite& block = meta->writeBlock;
    if (!block.isSet()) {
        const ModbusRequest request =
            meta->writeFunction == 16
                ? ModbusRequest::writeMultiple(quint8(m_slave), meta->address, registers)
                : ModbusRequest::writeSingle(quint8(m_slave), meta->address, registers.first());
        submitWrite(meta, request, registers, options, outcome, done, busyRetries);
        return;
    }
    // The device wants this setting in a larger frame (the DC controller's configuration and
    // GPIO writes, which also store): read the rest of the block so it keeps its values.
    m_client->submit(
        ModbusRequest::readHolding(quint8(m_slave), block.address, quint16(block.readCount())),
        this,
        [this, meta, registers, options, outcome, done,
         busyRetries](const ModbusResult& r) mutable {
            const BlockWrite& b = meta->writeBlock;
            if (!r.ok() || r.registers.size() != b.readCount()) {
                outcome.error = tr("not written: %1 is written together with 0x%2–0x%3, and "
                                   "reading those first failed: %4")
                                    .arg(nameFor(meta->name))
                                    .arg(b.address, 4, 16, QLatin1Char('0'))
                                    .arg(b.address + b.count - 1, 4, 16, QLatin1Char('0'))
                                    .arg(r.ok() ? tr("short reply") : r.errorText());
                done(outcome);
                return;
            }
            QVector<quint16> frame = r.registers;
            const int at = meta->address - b.address;
            for (int i = 0; i < registers.size(); ++i)
                frame[at + i] = registers.at(i);
            frame += b.tail;
            submitWrite(meta, ModbusRequest::writeMultiple(quint8(m_slave), b.address, frame),
                        registers, options, outcome, done, busyRetries);
        });
}

void DeviceSession::submitWrite(const ParameterMeta* meta, const ModbusRequest& request,
                                const QVector<quint16>& registers, const WriteOptions& options,
                                Outcome outcome, Done done, int busyRetries)
{
    outcome.sent = true;
    const QVector<quint16> written = registers;
    m_client->submit(
        request, this,
        [this, meta, written, options, outcome, done, busyRetries](const ModbusResult& r) mutable {
            if (!r.ok()) {
                outcome.unconfirmed =
                    r.error != ModbusError::Exception && r.error != ModbusError::NotConnected &&
                    r.error != ModbusError::InvalidRequest && r.error != ModbusError::Cancelled;
                // A busy drive executed nothing: a setting is sent again (never
                // a command, which the user sends again when the drive can run it).
                std::function<void()> again;
                if (busyRetries > 0 && meta->kind != QLatin1String("command"))
                    again = [this, meta, written, options, outcome, done, busyRetries] {
                        send(meta, written, options, outcome, done, busyRetries - 1);
                    };
                explainFailure(r, outcome, done, again);
                return;
            }
            emit this->written(meta->name);
            if (!options.verify || !meta->isReadable()) {
                outcome.ok = true;
                outcome.value = ValueCodec::decode(*meta, written, context());
                done(outcome);
                return;
            }
            verifyWrite(*meta, written, outcome, done);
        });
}

void DeviceSession::verifyWrite(const ParameterMeta& meta, const QVector<quint16>& written,
                                Outcome outcome, Done done)
{
    m_client->submit(
        readRequest(m_slave, meta), this,
        [this, &meta, written, outcome, done](const ModbusResult& r) mutable {
            if (!r.ok()) {
                outcome.error = tr("written, but reading it back failed: %1").arg(r.errorText());
                done(outcome);
                return;
            }
            acceptRegisters(meta.name, r.registers);
            outcome.value = ValueCodec::decode(meta, r.registers, context());
            if (r.registers != written) {
                outcome.mismatch = true;
                outcome.error =
                    tr("verification failed: wrote %1, the device holds %2")
                        .arg(ValueCodec::format(meta, ValueCodec::decode(meta, written, context()),
                                                context()),
                             ValueCodec::format(meta, outcome.value, context()));
                done(outcome);
                return;
            }
            outcome.ok = true;
            outcome.verified = true;
            done(outcome);
        });
}

void DeviceSession::explainFailure(const ModbusResult& result, Outcome outcome, Done done,
                                   std::function<void()> onBusy)
{
    outcome.error = result.errorText();
    const ParameterMeta* errorRegister = commErrorParameter(m_profile);
    if (result.error != ModbusError::Exception || !errorRegister) {
        done(outcome);
        return;
    }
    // The DBU leaves the reason for an exception in its communication error register.
    m_client->submit(readRequest(m_slave, *errorRegister), this,
                     [this, errorRegister, outcome, done, onBusy](const ModbusResult& r) mutable {
                         if (r.ok() && !r.registers.isEmpty()) {
                             const CodeTable* table = m_profile.codeTable(errorRegister->codeTable);
                             const qint64 code = r.registers.first();
                             const CodeEntry* entry = table ? table->find(code) : nullptr;
                             if (entry && entry->retry && onBusy) {
                                 onBusy();
                                 return;
                             }
                             const QString hex =
                                 QString::number(code, 16).toUpper() + QLatin1Char('h');
                             outcome.deviceError = entry ? hex + QLatin1Char(' ') + entry->name
                                                         : tr("error code %1").arg(hex);
                             outcome.error += QStringLiteral(" — ") + outcome.deviceError;
                         }
                         done(outcome);
                     });
}

} // namespace opentop
