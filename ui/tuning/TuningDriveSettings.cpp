#include "ui/tuning/TuningDriveSettings.h"

#include "model/session/DeviceSession.h"
#include "ui/tuning/NumberField.h"

#include <QPointer>

#include <optional>

namespace opentop {

TuningDriveSettings::TuningDriveSettings(DeviceSession* session, const TuningSpec& spec,
                                         QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_spec(spec)
{
}

void TuningDriveSettings::read()
{
    const QPointer<TuningDriveSettings> self(this);
    QStringList names{m_spec.speedMode};
    const QString maxCurrent = QStringLiteral("config.max_current");
    if (m_session->profile().parameter(maxCurrent))
        names << maxCurrent;
    m_session->readMany(names, [self, this, maxCurrent](const DeviceSession::ReadManyOutcome& r) {
        if (!self)
            return;
        const DeviceSession::Outcome mode = r.results.value(m_spec.speedMode);
        const TuningSpec::ClosedLoopMode* loop =
            mode.ok ? m_spec.closedLoop(int(mode.value.raw)) : nullptr;
        const bool closedLoop = loop != nullptr;
        if (!loop && !m_spec.closedLoopModes.isEmpty())
            loop = &m_spec.closedLoopModes.first();
        // The units of the closed-loop mode, also while the drive is in another.
        ValueContext context = m_session->context();
        if (loop) {
            const auto base = context.parameterRaw;
            const QString modeName = m_spec.speedMode;
            const qint64 closed = loop->mode;
            context.parameterRaw = [base, modeName, closed](const QString& p) {
                return p == modeName ? std::optional<qint64>(closed)
                                     : (base ? base(p) : std::nullopt);
            };
            if (const ParameterMeta* meta = m_session->profile().parameter(loop->feedback))
                m_unit = meta->specFor(context).unit;
        }
        if (const ParameterMeta* meta = m_session->profile().parameter(m_spec.command))
            m_scale = meta->specFor(context).scale;
        const DeviceSession::Outcome current = r.results.value(maxCurrent);
        m_maxCurrent = current.ok ? current.value.number : 0;
        m_modeNote = !mode.ok ? tr("Could not read the speed mode: %1").arg(mode.error)
                     : closedLoop
                         ? QString()
                         : tr("The drive is not in a closed-loop speed mode (now: %1). Choose "
                              "one on its settings page first.")
                               .arg(mode.value.text.isEmpty() ? NumberField::text(mode.value.raw)
                                                              : mode.value.text);
        emit changed();
    });
}

} // namespace opentop
