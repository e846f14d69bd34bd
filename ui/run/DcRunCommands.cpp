#include "ui/run/DcRunCommands.h"

#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace opentop {

namespace {

const QString kSpeedCommand = QStringLiteral("speedCommand");

} // namespace

DcRunCommands::DcRunCommands(DeviceSession* session, QWidget* parent)
    : QWidget(parent)
    , m_session(session)
    , m_speed(new QLineEdit(this))
    , m_speedUnit(new QLabel(this))
    , m_speedError(new QLabel(this))
    , m_setSpeed(new QPushButton(tr("Set s&peed"), this))
{
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    m_speed->setObjectName(QStringLiteral("speed"));
    m_speed->setPlaceholderText(tr("set point, e.g. 50 or -20"));
    m_speedError->setObjectName(QStringLiteral("speedError"));
    m_speedError->setWordWrap(true);
    m_speedError->setStyleSheet(QStringLiteral("color: #c00000;"));
    connect(m_speed, &QLineEdit::textChanged, this, &DcRunCommands::updateSpeed);
    m_setSpeed->setObjectName(QStringLiteral("setSpeed"));
    connect(m_setSpeed, &QPushButton::clicked, this, &DcRunCommands::requestSpeed);
    connect(m_speed, &QLineEdit::returnPressed, m_setSpeed, &QPushButton::click);
    grid->addWidget(new QLabel(tr("Speed command:"), this), 0, 0);
    grid->addWidget(m_speed, 0, 1);
    grid->addWidget(m_speedUnit, 0, 2);
    grid->addWidget(m_setSpeed, 0, 3);
    grid->addWidget(m_speedError, 1, 0, 1, 4);
    const auto addStop = [this, grid](const QString& text, const QString& name,
                                      RunControl::Action action, int column) {
        auto* button = new QPushButton(text, this);
        button->setObjectName(name);
        RunControl::Command c;
        c.action = action;
        connect(button, &QPushButton::clicked, this,
                [this, c] { emit commandRequested(c, false); });
        grid->addWidget(button, 2, column, 1, 2);
    };
    addStop(tr("&Brake (speed 0)"), QStringLiteral("brake"), RunControl::Action::Stop, 0);
    if (RoleEvaluator::parameter(m_session->profile(), QStringLiteral("coast")))
        addStop(tr("&Natural stop"), QStringLiteral("coast"), RunControl::Action::Coast, 2);
    updateSpeed();
}

void DcRunCommands::requestSpeed()
{
    const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), kSpeedCommand);
    const ValueCodec::Encoded e =
        ValueCodec::encodeText(*meta, m_speed->text().trimmed(), m_session->context());
    RunControl::Command c;
    c.action = RunControl::Action::Speed;
    c.speed = m_speed->text().trimmed();
    emit commandRequested(c, e.ok && e.raw != 0);
}

QString DcRunCommands::speedError() const
{
    return m_speedError->text();
}

void DcRunCommands::setBusy(bool busy)
{
    m_busy = busy;
    m_speed->setEnabled(!busy);
    updateSpeed();
}

void DcRunCommands::updateSpeed()
{
    const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), kSpeedCommand);
    const ValueContext context = m_session->context();
    QString unresolved;
    const ValueSpec& spec = meta->specFor(context, &unresolved);
    m_speedUnit->setText(unresolved.isEmpty()
                             ? tr("%1 (%2)").arg(spec.unit, ValueCodec::allowedText(*meta, context))
                             : tr("(reading %1…)").arg(unresolved));
    const QString text = m_speed->text().trimmed();
    QString error;
    if (!text.isEmpty() && unresolved.isEmpty()) {
        const ValueCodec::Encoded e = ValueCodec::encodeText(*meta, text, context);
        if (!e.ok)
            error = e.error;
    }
    m_speedError->setText(error);
    m_setSpeed->setEnabled(!m_busy && !text.isEmpty() && unresolved.isEmpty() && error.isEmpty());
}

} // namespace opentop
