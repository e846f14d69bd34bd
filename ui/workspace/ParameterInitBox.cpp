#include "workspace/ParameterInitBox.h"

#include "session/DeviceParameters.h"
#include "session/DeviceSession.h"
#include "session/ParameterInitialiser.h"
#include "widgets/ConfirmBox.h"

#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

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
    connect(m_button, &QPushButton::clicked, this, &ParameterInitBox::start);
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
        self->ask(plan.consequences, plan.command);
    });
}

void ParameterInitBox::ask(const QStringList& consequences, const QString& command)
{
    const DeviceSession* session = m_parameters->session();
    const int slave = session->slave();
    QString details = QStringLiteral("• ") + consequences.join(QStringLiteral("\n• "));
    const int edits = m_parameters->pendingNames().size();
    if (edits > 0)
        details += QStringLiteral("\n• ") +
                   tr("Your %n unwritten edit(s) of this drive are discarded.", nullptr, edits);
    details += QStringLiteral("\n\n") + tr("Sent: %1 to machine %2 only.").arg(command).arg(slave);
    m_confirmed = false;
    QMessageBox* box =
        ConfirmBox::ask(this, tr("Initialise drive %1").arg(slave),
                        tr("Reset every setting of drive %1 (%2) to its factory defaults?")
                            .arg(slave)
                            .arg(session->variant().isEmpty() ? session->profile().name
                                                              : session->variant().toUpper()),
                        tr("Initialise drive %1").arg(slave), [this] {
                            m_confirmed = true;
                            send();
                        });
    box->setInformativeText(details);
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
        self->setStatus(tr("Drive %1 initialised; reading its values again…").arg(slave), false);
        self->m_parameters->refresh({}, [self, slave](int failed) {
            if (!self)
                return;
            self->m_button->setEnabled(true);
            self->setStatus(
                failed ? tr("Drive %1 initialised; %n value(s) could not be read back (it may "
                            "answer only at the default communication settings now).",
                            nullptr, failed)
                             .arg(slave)
                       : tr("Drive %1 initialised to its factory defaults; values read again.")
                             .arg(slave),
                failed > 0);
            emit self->finished();
        });
    });
}

} // namespace opentop
