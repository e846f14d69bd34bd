#include "ui/alarms/AlarmsPage.h"

#include "model/bus/DriveName.h"
#include "model/session/DeviceSession.h"
#include "ui/alarms/AlarmFollower.h"
#include "ui/groups/GroupWriteCheck.h"
#include "ui/widgets/StaleLook.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

namespace {

QString modelOf(DeviceSession* session)
{
    const ProfileVariant* variant = session->profile().variant(session->variant());
    return variant ? variant->model : session->profile().name;
}

} // namespace

AlarmsPage::AlarmsPage(DeviceSession* session, QWidget* parent)
    : QWidget(parent)
    , m_session(session)
    // Parented to the session: a command under way outlives a page closed meanwhile.
    , m_history(new AlarmHistory(session, session))
    , m_title(new QLabel)
    , m_status(new QLabel)
    , m_records(new AlarmRecordsView(session))
    , m_reread(new QPushButton(tr("&Re-read")))
    , m_reset(new QPushButton(tr("Reset &alarm…")))
    , m_clear(new QPushButton(tr("&Clear records…")))
    , m_age(new QLabel)
{
    // One arg(): a name is text, never a place for the model.
    m_title->setText(tr("Alarms and warnings of machine %1 (%2)")
                         .arg(DriveName::listed(session), modelOf(session)));
    m_title->setTextFormat(Qt::PlainText); // the machine's name and model, as the drive has them
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_status->setWordWrap(true);

    auto* layout = new QVBoxLayout(this);
    // Tight: with every dock open on a 768-px laptop screen, and CJK rows taller, the page's
    // minimum height decides whether the window fits.
    layout->setSpacing(3);
    layout->setContentsMargins(layout->contentsMargins().left(), 4,
                               layout->contentsMargins().right(), 4);
    layout->addWidget(m_title);
    layout->addWidget(m_status);
    m_age->setVisible(false); // once the page follows the drive live
    layout->addWidget(m_age);
    layout->addWidget(m_records, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_reread);
    buttons->addStretch();
    buttons->addWidget(m_reset);
    buttons->addWidget(m_clear);
    layout->addLayout(buttons);

    m_reset->setToolTip(tr("Send the alarm reset command; tells whether the alarm is cleared or "
                           "only a power cycle clears it"));
    m_clear->setToolTip(tr("Erase the alarm and warning records kept by the drive"));
    connect(m_reread, &QPushButton::clicked, this, &AlarmsPage::refresh);
    connect(m_reset, &QPushButton::clicked, this, &AlarmsPage::resetAlarm);
    connect(m_clear, &QPushButton::clicked, this, &AlarmsPage::clearRecords);

    if (!m_history->supported())
        m_status->setText(tr("This drive keeps no alarm or warning records."));
    setBusy(false);
}

AlarmsPage::~AlarmsPage()
{
    // A command under way deletes the history when it ends (see guarded()).
    if (!m_busy)
        delete m_history.data();
}

void AlarmsPage::followLive(MonitorHub* hub, DriveStatusPoller* poller)
{
    const int slave = m_session->slave();
    m_follower = new AlarmFollower(
        slave, hub, poller,
        [this](std::optional<bool> active, std::optional<qint64> code) {
            return contradicts(active, code);
        },
        this);
    connect(m_follower, &AlarmFollower::readNeeded, this, &AlarmsPage::refresh);
    if (isVisible())
        m_follower->setWatching(true, this);
    // The alarm state shown is live while the drive answers the page's polling.
    m_look = m_follower->look();
    if (!m_look)
        return;
    m_look->addWidget(m_status);
    m_look->addWidget(m_age);
    connect(m_look, &StaleLook::evaluated, this,
            [this] { m_age->setText(tr("Alarm state: %1").arg(m_look->ageText())); });
    m_look->update();
    m_age->setVisible(true);
}

void AlarmsPage::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (m_follower)
        m_follower->setWatching(true, this);
}

void AlarmsPage::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    if (m_follower)
        m_follower->setWatching(false, this);
}

int AlarmsPage::autoRefreshes() const
{
    return m_follower ? m_follower->readsAsked() : 0;
}

std::optional<qint64> AlarmsPage::shownAlarmCode() const
{
    if (!report().alarmActive.value_or(false))
        return std::nullopt;
    const AlarmHistory::History* alarms = AlarmRecordsView::historyOf(report(), 0);
    if (!alarms || alarms->records.isEmpty() || alarms->records.first().empty)
        return std::nullopt;
    return alarms->records.first().code;
}

QString AlarmsPage::ageText() const
{
    return m_age->text();
}

bool AlarmsPage::contradicts(std::optional<bool> active, std::optional<qint64> code) const
{
    if (!active)
        return false; // the source does not tell
    const std::optional<bool> shown = shownAlarmActive();
    if (!shown || *shown != *active)
        return true;
    // Another alarm than the one shown (a code not read yet tells nothing).
    return *active && code && shownAlarmCode() != code;
}

template <typename T>
std::function<void(const T&)> AlarmsPage::guarded(void (AlarmsPage::*handler)(const T&))
{
    QPointer<AlarmsPage> self(this);
    QPointer<AlarmHistory> history = m_history;
    return [self, history, handler](const T& result) {
        if (!self) {
            if (history)
                history->deleteLater();
            return;
        }
        (self.data()->*handler)(result);
    };
}

void AlarmsPage::setBusy(bool busy, const QString& status)
{
    m_busy = busy;
    if (busy && m_follower)
        m_follower->setReading(true);
    const bool usable = m_history && m_history->supported() && !busy;
    m_reread->setEnabled(usable);
    m_reset->setEnabled(usable && m_history->canReset());
    m_clear->setEnabled(usable && m_history->canClear());
    if (!status.isEmpty())
        m_status->setText(status);
}

void AlarmsPage::refresh()
{
    if (m_busy || !m_history || !m_history->supported())
        return;
    setBusy(true, tr("Reading the records…"));
    m_history->read(guarded<AlarmHistory::Report>(&AlarmsPage::readDone));
}

void AlarmsPage::readDone(const AlarmHistory::Report& report)
{
    m_records->showReport(report);
    QStringList lines;
    if (!m_commandResult.isEmpty())
        lines << m_commandResult;
    m_commandResult.clear();
    if (report.alarmActive) {
        const AlarmHistory::History* alarms = AlarmRecordsView::historyOf(report, 0);
        const AlarmHistory::Record* newest =
            alarms && !alarms->records.isEmpty() ? &alarms->records.first() : nullptr;
        if (!*report.alarmActive)
            lines << tr("No alarm is active.");
        else if (newest && newest->entry)
            lines << tr("Alarm active: %1 %2.").arg(newest->entry->panel, newest->entry->name);
        else
            lines << tr("An alarm is active.");
    }
    if (report.powerRestartOnly)
        lines << tr("This drive is set to clear alarms by a power restart only (%1): Alarm-Reset "
                    "clears none of them.")
                     .arg(report.eraseMethod);
    for (const QString& e : report.errors)
        lines << tr("Could not be read: %1").arg(e);
    finish(lines.join(QLatin1Char('\n')));
}

void AlarmsPage::finish(const QString& status)
{
    setBusy(false);
    m_status->setText(status);
    emit operationFinished();
    // The drive's state changed meanwhile: the follower may ask for another read.
    if (m_follower)
        m_follower->setReading(false);
}

void AlarmsPage::confirm(const QString& title, const QString& text, const QString& details,
                         const QString& action, void (AlarmsPage::*then)())
{
    auto* box = new QMessageBox(QMessageBox::Question, title, text,
                                QMessageBox::Yes | QMessageBox::Cancel, this);
    box->setTextFormat(Qt::PlainText); // names the machine
    // A group parent's children execute the command too.
    const QString reach = GroupWriteCheck::reachText(m_session);
    box->setInformativeText(reach.isEmpty() ? details : details + QStringLiteral("\n\n") + reach);
    box->button(QMessageBox::Yes)->setText(action);
    box->setDefaultButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::ApplicationModal);
    connect(box, &QMessageBox::buttonClicked, this, [this, box, then](QAbstractButton* button) {
        if (button == box->button(QMessageBox::Yes))
            (this->*then)();
    });
    box->show();
}

void AlarmsPage::resetAlarm()
{
    if (m_busy || !m_history || !m_history->canReset())
        return;
    QStringList details{tr("Writes: %1").arg(m_history->resetPlan().join(QStringLiteral(", "))),
                        tr("This clears the active alarm if its cause is gone. Some alarms are "
                           "cleared only by a power cycle; the result tells.")};
    if (report().powerRestartOnly)
        details << tr("This drive is set to clear alarms by a power restart only (%1).")
                       .arg(report().eraseMethod);
    confirm(tr("Reset alarm"),
            tr("Send the alarm reset command to machine %1?").arg(DriveName::listed(m_session)),
            details.join(QStringLiteral("\n\n")), tr("Reset alarm"), &AlarmsPage::startReset);
}

void AlarmsPage::startReset()
{
    if (m_busy || !m_history)
        return;
    setBusy(true, tr("Sending the alarm reset…"));
    m_history->reset(guarded<AlarmHistory::ResetOutcome>(&AlarmsPage::resetDone));
}

void AlarmsPage::resetDone(const AlarmHistory::ResetOutcome& outcome)
{
    m_commandResult = tr("Alarm reset: %1").arg(outcome.explanation);
    if (outcome.powerCycleNeeded)
        m_commandResult +=
            QLatin1Char('\n') + tr("Turn the drive's power off, wait 5 s and turn it on again.");
    m_busy = false;
    refresh(); // the histories and the active alarm as they are now
}

void AlarmsPage::clearRecords()
{
    if (m_busy || !m_history || !m_history->canClear())
        return;
    QStringList erased;
    for (const AlarmHistory::History& h : report().histories)
        erased << (h.ok ? tr("%1 (%2 records)").arg(h.label).arg(h.used()) : h.label);
    if (erased.isEmpty())
        erased << tr("the alarm and warning records");
    confirm(
        tr("Clear records"),
        tr("Erase %1 of machine %2?").arg(erased.join(tr(" and ")), DriveName::listed(m_session)),
        tr("The records cannot be restored. Writes: %1")
            .arg(m_history->clearPlan().join(QStringLiteral(", "))),
        tr("Erase"), &AlarmsPage::startClear);
}

void AlarmsPage::startClear()
{
    if (m_busy || !m_history)
        return;
    setBusy(true, tr("Erasing the records…"));
    m_history->clearRecords(guarded<AlarmHistory::ClearOutcome>(&AlarmsPage::clearDone));
}

void AlarmsPage::clearDone(const AlarmHistory::ClearOutcome& outcome)
{
    QStringList lines;
    if (!outcome.cleared.isEmpty())
        lines << tr("Erased: %1 (%2 records); %3")
                     .arg(outcome.cleared.join(QStringLiteral(", ")))
                     .arg(outcome.erasedRecords)
                     .arg(outcome.verified ? tr("read back empty.")
                                           : tr("NOT empty when read back."));
    for (const QString& e : outcome.errors)
        lines << tr("Erasing failed: %1").arg(e);
    m_commandResult = lines.join(QLatin1Char('\n'));
    m_busy = false;
    refresh();
}

} // namespace opentop
