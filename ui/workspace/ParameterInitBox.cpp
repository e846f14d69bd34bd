#include "ui/workspace/ParameterInitBox.h"

#include "model/bus/DriveName.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "model/session/ParameterInitialiser.h"
#include "transport/ModbusClient.h"
#include "ui/groups/GroupWriteCheck.h"
#include "ui/widgets/ConfirmBox.h"
#include "ui/widgets/PlainText.h"

#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

namespace opentop {

namespace {

QPointer<QObject> s_reconnectOwner;
ParameterInitBox::ReconnectHandler s_reconnect;

} // namespace

void ParameterInitBox::setReconnectHandler(QObject* owner, ReconnectHandler handler)
{
    s_reconnectOwner = owner;
    s_reconnect = std::move(handler);
}

bool ParameterInitBox::supported(const DeviceParameters* parameters)
{
    return ParameterInitialiser(parameters->session()).supported();
}

ParameterInitBox::ParameterInitBox(DeviceParameters* parameters, QWidget* parent)
    : QGroupBox(tr("Parameter initialisation"), parent)
    , m_parameters(parameters)
    , m_initialiser(new ParameterInitialiser(parameters->session(), this))
    , m_status(new QLabel(this))
    , m_button(new QPushButton(this))
    , m_reconnect(new QPushButton(this))
{
    const int slave = parameters->session()->slave();
    auto* layout = new QVBoxLayout(this);
    auto* text = new QLabel(
        tr("Returns every setting of drive %1 to its factory default, including the "
           "communication settings: afterwards the drive may answer only at the default rate, "
           "and control priority goes back to its input terminals. The motor must be stopped. "
           "The consequences for this drive are listed before anything is sent.")
            .arg(slave),
        this);
    text->setWordWrap(true);
    layout->addWidget(text);
    m_button->setText(tr("&Initialise all parameters of drive %1…").arg(slave));
    m_button->setObjectName(QStringLiteral("parameterInit"));
    m_button->setToolTip(tr("Asks first, naming the drive and what changes"));
    layout->addWidget(m_button, 0, Qt::AlignLeft);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_status->hide();
    layout->addWidget(m_status);
    m_reconnect->setObjectName(QStringLiteral("parameterInitReconnect"));
    m_reconnect->hide();
    layout->addWidget(m_reconnect, 0, Qt::AlignLeft);
    connect(m_button, &QPushButton::clicked, this, &ParameterInitBox::start);
    connect(m_reconnect, &QPushButton::clicked, this, &ParameterInitBox::reconnect);
}

QString ParameterInitBox::statusText() const
{
    return m_status->text();
}

void ParameterInitBox::setStatus(const QString& text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(error ? QStringLiteral("color: #b01c1c;") : QString());
    m_status->setVisible(!text.isEmpty());
}

void ParameterInitBox::start()
{
    m_button->setEnabled(false);
    setStatus(tr("Reading what the initialisation would change…"), false);
    QPointer<ParameterInitBox> self(this);
    m_initialiser->check([self](const ParameterInitialiser::Plan& plan) {
        if (!self)
            return;
        if (!plan.refusal.isEmpty()) {
            self->m_button->setEnabled(true);
            self->setStatus(plan.refusal, true);
            emit self->finished();
            return;
        }
        self->setStatus(QString(), false);
        self->ask(plan);
    });
}

void ParameterInitBox::ask(const ParameterInitialiser::Plan& plan)
{
    m_plan = plan;
    const QString& command = plan.command;
    const DeviceSession* session = m_parameters->session();
    const int slave = session->slave();
    QString details = QStringLiteral("• ") + plan.consequences.join(QStringLiteral("\n• "));
    if (!plan.afterwards.isEmpty())
        details += QStringLiteral("\n\n") + tr("Afterwards:") + QStringLiteral("\n• ") +
                   plan.afterwards.join(QStringLiteral("\n• "));
    const int edits = m_parameters->pendingNames().size();
    if (edits > 0)
        details += QStringLiteral("\n• ") +
                   tr("Your %n unwritten edit(s) of this drive are discarded.", nullptr, edits);
    // A group parent's children execute the initialisation too.
    const QString reach = GroupWriteCheck::reachText(session);
    details +=
        QStringLiteral("\n\n") +
        (reach.isEmpty()
             ? tr("Sent: %1 to machine %2 only.").arg(command).arg(DriveName::listed(session))
             : tr("Sent: %1 to machine %2.").arg(command).arg(DriveName::listed(session)) +
                   QLatin1Char(' ') + reach);
    m_confirmed = false;
    QMessageBox* box = ConfirmBox::ask(
        this, tr("Initialise drive %1").arg(DriveName::listed(session)),
        tr("Reset every setting of %1 to its factory defaults?")
            .arg(DriveName::withModel(slave, session->machineName(),
                                      session->variant().isEmpty() ? session->profile().name
                                                                   : session->variant().toUpper())),
        tr("Initialise drive %1").arg(slave), [this] {
            m_confirmed = true;
            send();
        });
    box->setInformativeText(PlainText::asWritten(details)); // names the drive
    // Cancel, Escape or closing the box: nothing is sent.
    connect(box, &QDialog::finished, this, [this] {
        if (m_confirmed)
            return;
        m_button->setEnabled(true);
        setStatus(tr("Cancelled; nothing was sent."), false);
        emit finished();
    });
}

void ParameterInitBox::send()
{
    const int slave = m_parameters->session()->slave();
    setStatus(tr("Initialising drive %1…").arg(slave), false);
    QPointer<ParameterInitBox> self(this);
    m_initialiser->run([self, slave](const ParameterInitialiser::Outcome& o) {
        if (!self)
            return;
        if (!o.ok) {
            self->m_button->setEnabled(true);
            self->setStatus(
                o.sent
                    ? tr("Drive %1 did not confirm the initialisation: %2").arg(slave).arg(o.error)
                    : tr("Nothing was sent: %1").arg(o.error),
                true);
            emit self->finished();
            return;
        }
        // The drive holds its defaults now: drop the edits and read everything again.
        self->m_parameters->revertAll();
        const ConnectionSettings now = self->m_parameters->session()->client()->settings();
        const ConnectionSettings factory = self->reconnectSettings();
        if (self->m_plan.reconnectBaud > 0 && now.kind != ConnectionSettings::Kind::Tcp &&
            (factory.baud != now.baud || factory.parity != now.parity ||
             factory.stopBits != now.stopBits)) {
            self->m_reconnect->setText(
                tr("&Reconnect at %1 bit/s after the power-up").arg(self->m_plan.reconnectBaud));
            self->m_reconnect->setToolTip(self->m_plan.afterwards.join(QLatin1Char('\n')));
            self->m_reconnect->show();
        }
        self->setStatus(tr("Drive %1 initialised; reading its values again…").arg(slave), false);
        self->m_parameters->refresh({}, [self, slave](int failed) {
            if (!self)
                return;
            self->m_button->setEnabled(true);
            QString text =
                failed ? tr("Drive %1 initialised; %n value(s) could not be read back (it may "
                            "answer only at the default communication settings now).",
                            nullptr, failed)
                             .arg(slave)
                       : tr("Drive %1 initialised to its factory defaults; values read again.")
                             .arg(slave);
            for (const QString& step : self->m_plan.afterwards)
                text += QLatin1Char('\n') + step;
            self->setStatus(text, failed > 0);
            emit self->finished();
        });
    });
}

ConnectionSettings ParameterInitBox::reconnectSettings() const
{
    ConnectionSettings settings = m_parameters->session()->client()->settings();
    if (m_plan.reconnectBaud > 0) {
        settings.baud = m_plan.reconnectBaud;
        settings.parity = m_plan.reconnectParity;
        settings.stopBits = m_plan.reconnectStopBits;
    }
    return settings;
}

void ParameterInitBox::reconnect()
{
    const ConnectionSettings settings = reconnectSettings();
    m_reconnect->setEnabled(false);
    // The drive needs its power-on delay before it communicates (DBU manual 11-2: 1 s).
    setStatus(tr("Reconnecting at %1 bit/s in %2 s…")
                  .arg(settings.baud)
                  .arg(m_plan.powerOnDelayMs / 1000.0, 0, 'f', 1),
              false);
    QPointer<ParameterInitBox> self(this);
    QTimer::singleShot(m_plan.powerOnDelayMs, this, [self, settings] {
        if (!self)
            return;
        self->m_reconnect->hide();
        self->m_reconnect->setEnabled(true);
        if (s_reconnectOwner && s_reconnect)
            s_reconnect(settings); // may delete this box with the old connection's pages
        else if (self)
            self->setStatus(tr("Reconnect at %1 bit/s from the Bus menu.").arg(settings.baud),
                            true);
    });
}

} // namespace opentop
