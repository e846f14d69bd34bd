#include "ui/eol/StationActions.h"

#include "model/access/AccessPolicy.h"
#include "model/access/StationAccess.h"
#include "model/io/DisplayText.h"
#include "model/station/EolStation.h"
#include "ui/eol/IdentityDialog.h"
#include "ui/widgets/PlainText.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

namespace opentop {

StationActions::StationActions(EolStation* station, std::function<ModbusClient*()> client,
                               std::function<QString()> operatorName, QWidget* parent)
    : QWidget(parent)
    , m_station(station)
    , m_client(std::move(client))
    , m_operatorName(std::move(operatorName))
    , m_text(new QLabel(this))
    , m_reset(new QPushButton(tr("Reset alarm and test again"), this))
    , m_retest(new QPushButton(tr("Technician: test again…"), this))
{
    setObjectName(QStringLiteral("stationActions"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::PlainText); // serials, reasons, drive texts
    for (QPushButton* b : {m_reset, m_retest}) {
        QFont f = b->font();
        f.setPointSizeF(f.pointSizeF() * 1.3);
        f.setBold(true);
        b->setFont(f);
        b->setFocusPolicy(Qt::NoFocus); // the serial field keeps the scanner's keys
    }
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_reset);
    layout->addWidget(m_retest);
    clear();

    connect(m_station, &EolStation::unitStarted, this, &StationActions::clear);
    connect(m_station, &EolStation::unitFinished, this, &StationActions::unitFinished);
    connect(m_station, &EolStation::retestNeedsTechnician, this,
            [this](const QString& serial, const QString& why) {
                m_retestSerial = serial;
                m_retestWhy = why; // shown under the verdict; asked again when allowing
                show(tr("A technician may allow unit %1 to be tested again.").arg(serial),
                     m_retest);
            });
    connect(m_station, &EolStation::alarmResetStarted, this, [this](const QVector<int>& drives) {
        QStringList names;
        for (int n : drives)
            names << QString::number(n);
        show(tr("Resetting the alarm of machine number %1…").arg(names.join(QStringLiteral(", "))),
             nullptr);
    });
    connect(m_station, &EolStation::alarmResetFinished, this,
            [this](bool cleared, const QStringList& texts) {
                if (cleared) {
                    clear(); // the unit starts again by itself
                    return;
                }
                show(tr("The alarm is not cleared; nothing was started:\n%1")
                         .arg(texts.join(QLatin1Char('\n'))),
                     m_reset);
            });
    connect(m_reset, &QPushButton::clicked, this, [this] {
        StationAccess* access = m_station->access();
        const auto& user = access->user();
        // The logged-in operator may reset (AccessPolicy); anyone else is asked who they are.
        if (access->mayBeManaged() &&
            !(user && AccessPolicy::allows(user->role, Privilege::ResetAlarm))) {
            IdentityDialog::ask(access, Privilege::ResetAlarm, tr("reset the alarm"), this,
                                [this](const AccessDecision&) { resetAlarms(); });
            return;
        }
        if (user)
            access->audit(QStringLiteral("reset-alarm"),
                          tr("serial %1").arg(DisplayText::escaped(m_station->lastSerial())));
        resetAlarms();
    });
    connect(m_retest, &QPushButton::clicked, this, [this] {
        StationAccess* access = m_station->access();
        if (access->mayBeManaged()) {
            // A technician (or higher) identifies themselves; the dialog audits it.
            IdentityDialog::ask(
                access, Privilege::OverrideRetestLimit,
                tr("test serial %1 again").arg(DisplayText::escaped(m_retestSerial)), this,
                [this](const AccessDecision& d) { retestBy(d.user ? d.user->name : QString()); });
            return;
        }
        retestBy(whoAllows());
    });
}

void StationActions::unitFinished(const UnitRecord& record)
{
    if (record.status == UnitStatus::Error && !m_station->latchedAlarms().isEmpty()) {
        QStringList names;
        for (int n : m_station->latchedAlarms())
            names << QString::number(n);
        show(tr("An alarm was active on machine number %1 before the test: nothing was written. "
                "Reset it (the drive's own reset; one that needs a power cycle says so) and the "
                "unit is tested again.")
                 .arg(names.join(QStringLiteral(", "))),
             m_reset);
        return;
    }
    clear();
}

void StationActions::resetAlarms()
{
    m_reset->setEnabled(false);
    m_station->resetAlarmsAndRetry(m_client());
}

void StationActions::retestBy(const QString& by)
{
    if (by.isEmpty())
        return;
    QString error;
    clear();
    if (!m_station->startAgain(m_client(), by, &error))
        show(error, nullptr);
}

QString StationActions::whoAllows()
{
    const QString name = m_operatorName();
    const QString who = name.isEmpty() ? tr("(no name)") : name;
    const auto answer = PlainText::question(
        this, tr("Test again"),
        tr("%1\n\nTest unit %2 again? It is recorded as allowed by %3.")
            .arg(DisplayText::escapedLines(m_retestWhy), DisplayText::escaped(m_retestSerial),
                 DisplayText::escaped(who)));
    return answer == QMessageBox::Yes ? who : QString();
}

void StationActions::show(const QString& text, QPushButton* button)
{
    m_text->setText(DisplayText::escapedLines(text)); // quotes serials and reasons
    m_reset->setVisible(button == m_reset);
    m_retest->setVisible(button == m_retest);
    m_reset->setEnabled(true);
    m_retest->setEnabled(true);
    setVisible(true);
}

void StationActions::clear()
{
    m_text->clear();
    m_reset->hide();
    m_retest->hide();
    setVisible(false);
}

} // namespace opentop
