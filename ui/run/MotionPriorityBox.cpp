#include "ui/run/MotionPriorityBox.h"
#include "model/bus/DriveName.h"
#include "ui/groups/GroupWriteCheck.h"

#include "model/profile/RoleEvaluator.h"
#include "model/run/ExitActions.h"
#include "model/session/DeviceSession.h"
#include "ui/widgets/ConfirmBox.h"

#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

namespace {

const QString kPriority = QStringLiteral("motionPriority");

} // namespace

MotionPriorityBox::MotionPriorityBox(BusDrives* drives, DeviceSession* session, QWidget* parent)
    : QFrame(parent)
    , m_drives(drives)
    , m_session(session)
{
    setFrameShape(QFrame::StyledPanel);
    auto* layout = new QVBoxLayout(this);
    m_text = new QLabel(this);
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::PlainText); // names the machine
    layout->addWidget(m_text);
    auto* button = new QPushButton(tr("Switch to communication priority…"), this);
    button->setObjectName(QStringLiteral("switchPriority"));
    connect(button, &QPushButton::clicked, this, &MotionPriorityBox::askToSwitch);
    layout->addWidget(button, 0, Qt::AlignLeft);
}

QString MotionPriorityBox::wantedLabel() const
{
    const ParameterMeta* priority = RoleEvaluator::parameter(m_session->profile(), kPriority);
    const qint64 wanted = m_session->profile().role(kPriority)->value.value_or(0);
    const ValueContext context = m_session->context();
    QString label = RoleEvaluator::valueText(*priority, wanted, context);
    for (const EnumOption& e : priority->specFor(context).options) {
        if (e.value == wanted)
            label = e.label;
    }
    return label;
}

void MotionPriorityBox::setCurrent(const QString& current)
{
    const ParameterMeta* priority = RoleEvaluator::parameter(m_session->profile(), kPriority);
    if (!priority)
        return;
    m_text->setText(
        tr("Machine number %1 is in \"%2\" (%3): it takes run, stop, direction and speed "
           "selection from its input terminals and refuses motion commands over the bus, so the "
           "test run is disabled.\n\nSwitching to \"%4\" hands these commands to the bus: the "
           "input terminals no longer start or stop the motor, and the machine's own controls "
           "stay without effect until you switch back to \"%2\".")
            .arg(DriveName::listed(m_session))
            .arg(current, priority->label, wantedLabel()));
}

QString MotionPriorityBox::explanation() const
{
    return m_text->text();
}

QString MotionPriorityBox::alsoReaches() const
{
    // A group parent's priority write is executed by its children too (manual 11-3).
    const QString reach = GroupWriteCheck::reachText(m_session);
    return reach.isEmpty() ? QString() : QStringLiteral("\n\n") + reach;
}

void MotionPriorityBox::askToSwitch()
{
    const ParameterMeta* priority = RoleEvaluator::parameter(m_session->profile(), kPriority);
    if (!priority)
        return;
    ConfirmBox::ask(this, tr("Switch to communication priority"),
                    tr("Machine number %1 will take run, stop, direction and speed selection "
                       "from the bus (%2 = \"%3\"). Its input terminals then no longer start or "
                       "stop the motor.")
                            .arg(DriveName::listed(m_session))
                            .arg(priority->label, wantedLabel()) +
                        alsoReaches(),
                    tr("Switch"), [this] { sendSwitch(); });
}

void MotionPriorityBox::sendSwitch()
{
    const ParameterMeta* priority = RoleEvaluator::parameter(m_session->profile(), kPriority);
    const qint64 wanted = m_session->profile().role(kPriority)->value.value_or(0);
    DeviceSession::WriteOptions explicitly;
    explicitly.explicitCommand = true;
    emit switching(tr("Switching to communication priority…"));
    QPointer<MotionPriorityBox> self(this);
    m_session->write(
        priority->name, RoleEvaluator::writeText(*priority, wanted, m_session->context()),
        explicitly, [self](const DeviceSession::Outcome& o) {
            if (!self)
                return;
            emit self->switched(
                o.ok, o.ok ? tr("Machine number %1 takes motion commands over the bus now.")
                                 .arg(DriveName::listed(self->m_session))
                           : tr("Cannot switch the control priority: %1").arg(o.error));
        });
}

void MotionPriorityBox::askToReturn(QWidget* parent)
{
    const int slave = m_session->slave();
    const QString named = DriveName::listed(m_session);
    QPointer<MotionPriorityBox> self(this);
    ConfirmBox::ask(
        parent, tr("Return to I/O priority"),
        tr("Machine number %1 will take run, stop, direction and speed selection from its input "
           "terminals again, and refuse motion commands over the bus. If an input says run, the "
           "motor runs.")
                .arg(named) +
            alsoReaches(),
        tr("Return to I/O priority"), [self, slave, named] {
            if (!self)
                return;
            emit self->switching(tr("Returning to I/O priority…"));
            auto* actions = new ExitActions(self->m_drives, self);
            actions->returnToIoPriority({slave}, [self, actions, named](const QStringList& failed) {
                actions->deleteLater();
                if (!self)
                    return;
                emit self->switched(
                    failed.isEmpty(),
                    failed.isEmpty()
                        ? tr("Machine number %1 follows its input terminals again.").arg(named)
                        : failed.join(QLatin1Char('\n')));
            });
        });
}

} // namespace opentop
