#include "model/session/DeviceSession.h"

#include "model/profile/ValueCodec.h"
#include "model/session/BlockReader.h"
#include "model/session/BlockWriter.h"
#include "model/session/DependentValues.h"
#include "model/session/DeviceRefusal.h"
#include "model/session/MissingValues.h"
#include "model/session/ReachedDrives.h"
#include "transport/ModbusClient.h"

#include <utility>

namespace opentop {

QString DeviceSession::reachedProblem(const QString& name, const QVector<quint16>& registers) const
{
    const ParameterMeta* meta = m_profile.parameter(name);
    if (!meta || !m_reach)
        return QString();
    return ReachedDrives(const_cast<DeviceSession*>(this), reachedDrives())
        .problem(*meta, registers, {}, false);
}

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
    m_client->submit(BlockReader::requestFor(m_slave, *meta), this,
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
    BlockReader::read(this, names, std::move(done), priority);
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
    MissingValues(this).readControlling(*meta, [this, meta, text, options, outcome,
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
        MissingValues(this).read(dependents, [this, meta, registers, options, outcome,
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
            // The drives that execute it too must allow it as well, by their own profile,
            // variant and values; nothing is sent before. They are read back after it.
            const ReachedDrives reached(this, reachedDrives());
            reached.check(*meta, registers, options.companions,
                          [this, meta, registers, options, outcome, done,
                           reached](const QString& refused) mutable {
                              if (!refused.isEmpty()) {
                                  outcome.error = refused; // nothing is sent
                                  done(outcome);
                                  return;
                              }
                              send(meta, registers, options, outcome,
                                   reached.verifying(meta, registers, done));
                          });
        });
    });
}

void DeviceSession::send(const ParameterMeta* meta, const QVector<quint16>& registers,
                         const WriteOptions& options, Outcome outcome, Done done, int busyRetries)
{
    BlockWriter::frame(this, *meta, registers,
                       [this, meta, registers, options, outcome, done,
                        busyRetries](const ModbusRequest& request, const QString& error) mutable {
                           if (!error.isEmpty()) {
                               outcome.error = error; // nothing was sent
                               done(outcome);
                               return;
                           }
                           submitWrite(meta, request, registers, options, outcome, done,
                                       busyRetries);
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
        BlockReader::requestFor(m_slave, meta), this,
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
    DeviceRefusal::read(m_client, this, m_profile, m_slave, result,
                        [outcome, done, onBusy](const DeviceRefusal::Reason& why) mutable {
                            if (why.retry && onBusy) {
                                onBusy();
                                return;
                            }
                            if (!why.code.isEmpty()) {
                                outcome.deviceError = why.code;
                                outcome.error += QStringLiteral(" — ") + why.code;
                            }
                            if (why.entry) {
                                outcome.explanation = why.entry->explained();
                                outcome.deviceCode = int(why.entry->code);
                            }
                            done(outcome);
                        });
}

} // namespace opentop
