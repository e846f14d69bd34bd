#include "model/tuning/TuningRunner.h"

#include "model/session/DeviceSession.h"
#include "model/tuning/RelayAutotune.h"
#include "model/tuning/StepTest.h"
#include "model/tuning/TuningDrive.h"

#include <QPointer>

namespace opentop {

TuningRunner::TuningRunner(DeviceSession* session, const TuningSpec& spec, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_spec(spec)
    , m_drive(std::make_unique<TuningDrive>(session, spec))
    , m_step(std::make_unique<StepTest>(m_drive.get()))
    , m_relay(std::make_unique<RelayAutotune>(m_drive.get()))
{
    connect(m_drive.get(), &TuningDrive::sampled, this, &TuningRunner::sampled);
    connect(m_drive.get(), &TuningDrive::phase, this, &TuningRunner::phase);
}

// A test still running when the runner goes: the drive sends the stop (~TuningDrive).
TuningRunner::~TuningRunner() = default;

void TuningRunner::setLimits(const Limits& limits)
{
    m_drive->setLimits(limits);
}

const TuningRunner::Limits& TuningRunner::limits() const
{
    return m_drive->limits();
}

void TuningRunner::setClock(std::function<double()> nowMs)
{
    m_drive->setClock(std::move(nowMs));
}

void TuningRunner::startStep(const StepPlan& plan, Done done)
{
    m_step->start(plan, std::move(done));
}

void TuningRunner::startAutotune(const RelayPlan& plan, Done done)
{
    m_relay->start(plan, std::move(done));
}

void TuningRunner::cancel()
{
    m_drive->cancel();
}

bool TuningRunner::isRunning() const
{
    return m_drive->isRunning();
}

const QStringList& TuningRunner::stateTrail() const
{
    return m_drive->states().trail();
}

void TuningRunner::readGains(GainsDone done)
{
    m_session->readMany(m_spec.gainParameters(),
                        [self = QPointer(this), this, done](const auto& r) {
                            if (!self)
                                return;
                            PidGains g;
                            for (const QString& name : m_spec.gainParameters()) {
                                const DeviceSession::Outcome o = r.results.value(name);
                                if (!o.ok) {
                                    done(false, g, o.error);
                                    return;
                                }
                            }
                            g.p = r.results.value(m_spec.gainP).value.number;
                            g.i = r.results.value(m_spec.gainI).value.number;
                            g.d = r.results.value(m_spec.gainD).value.number;
                            g.dPeriodMs = int(r.results.value(m_spec.dPeriod).value.number);
                            done(true, g, QString());
                        });
}

void TuningRunner::writeGains(const PidGains& gains, GainsDone done)
{
    writeGainsFrom(gains, 0, std::move(done));
}

void TuningRunner::writeGainsFrom(const PidGains& gains, int k, GainsDone done)
{
    const QVector<QPair<QString, double>> values = {{m_spec.gainP, gains.p},
                                                    {m_spec.gainI, gains.i},
                                                    {m_spec.gainD, gains.d},
                                                    {m_spec.dPeriod, double(gains.dPeriodMs)}};
    if (k == values.size()) {
        readGains(done);
        return;
    }
    DeviceSession::WriteOptions options;
    m_session->write(
        values[k].first, QString::number(values[k].second, 'g', 7), options,
        [self = QPointer(this), this, k, done, gains](const DeviceSession::Outcome& o) {
            if (!self)
                return;
            if (!o.ok) {
                done(false, gains, o.error);
                return;
            }
            writeGainsFrom(gains, k + 1, done);
        });
}

void TuningRunner::storeGains(std::function<void(bool, const QString&)> done)
{
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    options.verify = false;
    m_session->write(m_spec.store, QString::number(m_spec.storeValue), options,
                     [done](const DeviceSession::Outcome& o) { done(o.ok, o.error); });
}

} // namespace opentop
