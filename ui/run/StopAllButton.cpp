#include "ui/run/StopAllButton.h"

#include "ui/run/StopAllKeys.h"

#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <QHash>
#include <QMessageBox>

namespace opentop {

StopAllButton::StopAllButton(BusDrives* drives, QWidget* parent)
    : QPushButton(tr("STOP ALL"), parent)
    , m_drives(drives)
{
    setObjectName(QStringLiteral("stopAll"));
    setToolTip(tr("Stops every drive on the bus at once (%1), then checks that each has stopped.")
                   .arg(shortcuts().first().toString(QKeySequence::NativeText)));
    setFocusPolicy(Qt::StrongFocus);
    setAutoDefault(false);
    setMinimumHeight(48);
    setMinimumWidth(140);
    QFont f = font();
    f.setBold(true);
    f.setPointSizeF(f.pointSizeF() * 1.5);
    setFont(f);
    setStyleSheet(QStringLiteral(
        "QPushButton { background-color: #d00000; color: white; border: 2px solid #700000; "
        "border-radius: 6px; padding: 6px 16px; }"
        "QPushButton:pressed { background-color: #900000; }"
        "QPushButton:focus { border: 3px solid #ffd000; }"));
    connect(this, &QPushButton::clicked, this, &StopAllButton::stopAll);
}

QList<QKeySequence> StopAllButton::shortcuts()
{
    return {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), QKeySequence(Qt::Key_Pause)};
}

void StopAllButton::install(QWidget* window)
{
    QPointer<QWidget> guarded(window);
    new StopAllKeys(
        [guarded]() -> StopAllButton* {
            return guarded ? guarded->findChild<StopAllButton*>() : nullptr;
        },
        window);
}

QMessageBox* StopAllButton::resultWindow() const
{
    return m_result.data();
}

void StopAllButton::stopAll()
{
    // Every press sends the broadcast again; stopping is never refused or delayed.
    QVector<int> known;
    for (int slave : m_drives->slaves()) {
        if (m_drives->info(slave).state == DeviceInfo::State::Present)
            known << slave;
    }
    auto* stop = new StopAll(m_drives->client(), ProfileRegistry::builtIn(), this);
    // A recipe's positions are checked whether a scan found them or not (a station restarted
    // after a crash has not scanned): a session of their family, for this stop only.
    QHash<int, DeviceSession*> expected;
    if (m_expected) {
        for (const auto& [slave, family] : m_expected()) {
            const Profile* profile = ProfileRegistry::builtIn().family(family);
            if (known.contains(slave) || !profile || m_drives->session(slave))
                continue;
            known << slave;
            expected.insert(
                slave, new DeviceSession(m_drives->client(), *profile, slave, QString(), stop));
        }
    }
    BusDrives* drives = m_drives;
    stop->setSessionLookup([drives, expected](int slave) {
        DeviceSession* session = drives->session(slave);
        return session ? session : expected.value(slave);
    });
    stop->setTiming(m_timing);
    ++m_running;
    setText(tr("STOPPING…"));
    emit started();
    stop->run(known, [this, stop](const StopReport& report) {
        stop->deleteLater();
        if (--m_running == 0)
            setText(tr("STOP ALL"));
        showReport(report);
        emit finished(report);
    });
}

QString StopAllButton::describe(const StopReport& report, const BusDrives* drives)
{
    QStringList lines;
    for (const StopBroadcast& b : report.broadcasts) {
        if (!b.sent)
            lines << tr("The stop broadcast to %1 drives FAILED: %2").arg(b.family, b.error);
    }
    if (report.drives.isEmpty())
        lines << tr("Stop sent to every drive. No drives are known on the bus, so none was "
                    "checked; scan the bus to have them checked.");
    for (const StopResult& r : report.drives) {
        const QString after = ValueCodec::formatNumber(r.elapsedMs / 1000.0, 1);
        const QString slave = drives ? drives->listed(r.slave) : QString::number(r.slave);
        QString line;
        switch (r.state) {
        case StopResult::State::Stopped:
            line = tr("Machine number %1: stopped after %2 s").arg(slave).arg(after);
            break;
        case StopResult::State::StillRunning:
            line = tr("Machine number %1: STILL RUNNING (%2)").arg(slave).arg(r.speedText);
            break;
        case StopResult::State::NoAnswer:
            line = tr("Machine number %1: NO ANSWER, not confirmed stopped").arg(slave);
            break;
        }
        if (!r.detail.isEmpty() && r.state != StopResult::State::Stopped)
            line += QStringLiteral(" — ") + r.detail;
        lines << line;
    }
    return lines.join(QLatin1Char('\n'));
}

void StopAllButton::showReport(const StopReport& report)
{
    m_reportText = describe(report, m_drives);
    const bool ok = report.broadcastOk() && report.allStopped();
    // With no drive known nothing was checked: the title must not claim they stopped.
    const QString title = !report.broadcastOk()     ? tr("STOP ALL: the stop broadcast FAILED")
                          : report.drives.isEmpty() ? tr("STOP ALL: stop sent, no drive checked")
                          : ok                      ? tr("STOP ALL: every drive stopped")
                               : tr("STOP ALL: not every drive is confirmed stopped");
    m_reportTitle = title;
    if (m_result)
        m_result->close();
    auto* box = new QMessageBox(ok && !report.drives.isEmpty() ? QMessageBox::Information
                                                               : QMessageBox::Warning,
                                title, m_reportText, QMessageBox::Close, window());
    if (!ok)
        box->setIcon(QMessageBox::Critical);
    box->setTextFormat(Qt::PlainText); // the drives by their names
    box->setObjectName(QStringLiteral("stopAllResult"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    box->setModal(false);
    m_result = box;
    box->show();
}

} // namespace opentop
