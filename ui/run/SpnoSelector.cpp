#include "ui/run/SpnoSelector.h"

#include "model/profile/RoleEvaluator.h"
#include "model/profile/RunningData.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <QDateTime>
#include <QLocale>
#include <QPointer>

namespace opentop {

SpnoSelector::SpnoSelector(DeviceSession* session, QWidget* parent)
    : QComboBox(parent)
    , m_session(session)
{
    setObjectName(QStringLiteral("spno"));
    setSizeAdjustPolicy(QComboBox::AdjustToContents);
    const ParameterMeta* select =
        RoleEvaluator::parameter(session->profile(), QStringLiteral("select"));
    if (!select)
        return;
    for (const EnumOption& o : select->specFor(session->context()).options) {
        addItem(o.label, int(o.value + 1)); // running data N is code N-1
        setItemData(count() - 1, o.label, Qt::UserRole + 1);
    }
    connect(this, qOverload<int>(&QComboBox::activated), this, [this] { m_userChose = true; });
    setToolTip(tr("The running data that Select running data sends; \"The drive now\" shows the "
                  "running data the drive runs"));
}

void SpnoSelector::refreshLabels()
{
    const Profile& profile = m_session->profile();
    QStringList names;
    for (int i = 0; i < count(); ++i) {
        for (const char* field : {"speed", "direction"}) {
            const QString n =
                RunningData::parameter(profile, itemData(i).toInt(), QLatin1String(field));
            if (!n.isEmpty() && profile.parameter(n)->isReadable())
                names << n;
        }
    }
    const ParameterMeta* selected = RoleEvaluator::parameter(profile, QStringLiteral("selected"));
    if (selected && selected->isReadable())
        names << selected->name;
    if (names.isEmpty())
        return;
    QPointer<SpnoSelector> self(this);
    m_session->readMany(
        names,
        [self](const DeviceSession::ReadManyOutcome& o) {
            if (!self)
                return;
            const Profile& prof = self->m_session->profile();
            for (int i = 0; i < self->count(); ++i) {
                const int spno = self->itemData(i).toInt();
                QStringList parts;
                for (const char* field : {"speed", "direction"}) {
                    const QString n = RunningData::parameter(prof, spno, QLatin1String(field));
                    const DeviceSession::Outcome r = o.results.value(n);
                    if (!n.isEmpty() && r.value.valid)
                        parts << ValueCodec::format(*prof.parameter(n), r.value,
                                                    self->m_session->context());
                }
                const QString base = self->itemData(i, Qt::UserRole + 1).toString();
                self->setItemText(
                    i, parts.isEmpty() ? base
                                       : tr("%1 — %2").arg(base, parts.join(QStringLiteral(", "))));
            }
            const std::optional<int> running =
                RunningData::selected(prof, [&o](const QString& name) {
                    const DeviceSession::Outcome r = o.results.value(name);
                    return r.value.valid ? std::optional<double>(r.value.raw) : std::nullopt;
                });
            self->m_driveSpno = running;
            if (running) {
                // Until the user picks one, the entry shown is the one the drive runs: SPno1
                // beside a drive running SPno4 reads as a contradiction.
                if (!self->m_userChose && self->findData(*running) >= 0)
                    self->setCurrentIndex(self->findData(*running));
                self->setToolTip(
                    tr("The running data that Select running data sends. The drive reported "
                       "SPno%1 at %2; \"The drive now\" shows what it runs now.")
                        .arg(*running)
                        .arg(QLocale().toString(QTime::currentTime(), QStringLiteral("HH:mm:ss"))));
            }
            emit self->labelsRefreshed();
        },
        ModbusRequest::Priority::Poll);
}

} // namespace opentop
