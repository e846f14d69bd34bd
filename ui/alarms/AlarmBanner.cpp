#include "ui/alarms/AlarmBanner.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveStatusPoller.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace opentop {

AlarmBanner::AlarmBanner(DriveStatusPoller* poller, QWidget* parent)
    : QWidget(parent)
    , m_poller(poller)
    , m_label(new QLabel)
    , m_show(new QPushButton(tr("Show")))
    , m_dismiss(new QPushButton(tr("Dismiss")))
{
    setObjectName(QStringLiteral("alarmBanner"));
    setAttribute(Qt::WA_StyledBackground);
    setStyleSheet(QStringLiteral("#alarmBanner { background: #c62828; }"
                                 "#alarmBanner QLabel { color: white; font-weight: bold; }"));
    m_label->setWordWrap(true);
    m_show->setToolTip(tr("Open the drive's alarm history"));
    m_dismiss->setToolTip(tr("Hide this alarm until it is cleared; a new alarm shows again"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->addWidget(m_label, 1);
    layout->addWidget(m_show);
    layout->addWidget(m_dismiss);
    connect(m_show, &QPushButton::clicked, this, [this] {
        if (m_slave)
            emit showAlarms(m_slave);
    });
    connect(m_dismiss, &QPushButton::clicked, this, &AlarmBanner::dismiss);
    connect(poller, &DriveStatusPoller::statusChanged, this, &AlarmBanner::refresh);
    connect(poller->drives(), &BusDrives::driveRemoved, this, &AlarmBanner::refresh);
    refresh();
}

QString AlarmBanner::text() const
{
    return m_slave ? m_label->text() : QString();
}

QString AlarmBanner::alarmKey(int slave) const
{
    const DriveStatus s = m_poller->status(slave);
    if (!s.alarmActive.value_or(false))
        return QString();
    return s.alarmCode ? QString::number(*s.alarmCode) : QStringLiteral("?");
}

void AlarmBanner::dismiss()
{
    if (!m_slave)
        return;
    m_dismissed.insert(m_slave, alarmKey(m_slave));
    refresh();
}

void AlarmBanner::refresh()
{
    QVector<int> active;
    for (int slave : m_poller->drives()->slaves()) {
        const QString key = alarmKey(slave);
        // A dismissal lasts as long as that alarm: once it clears or changes, it is forgotten.
        if (m_dismissed.contains(slave) && m_dismissed.value(slave) != key)
            m_dismissed.remove(slave);
        if (!key.isEmpty() && !m_dismissed.contains(slave))
            active << slave;
    }
    for (auto it = m_dismissed.begin(); it != m_dismissed.end();)
        it = m_poller->drives()->contains(it.key()) ? std::next(it) : m_dismissed.erase(it);

    m_slave = active.value(0);
    if (!m_slave) {
        m_label->clear();
        hide();
        return;
    }
    const DriveStatus s = m_poller->status(m_slave);
    QString text;
    if (s.alarm && !s.alarm->remedy.isEmpty())
        text = tr("Machine %1: %2 %3 — %4")
                   .arg(m_slave)
                   .arg(s.alarm->panel, s.alarm->name, s.alarm->remedy);
    else if (s.alarm)
        text = tr("Machine %1: %2 %3").arg(m_slave).arg(s.alarm->panel, s.alarm->name);
    else if (s.alarmCode)
        text = tr("Machine %1: alarm %2h (not in the alarm table)")
                   .arg(m_slave)
                   .arg(QString::number(*s.alarmCode, 16).toUpper());
    else
        text = tr("Machine %1: an alarm is active").arg(m_slave);
    if (active.size() > 1)
        text += QLatin1Char(' ') +
                tr("(%n more drive(s) with an alarm)", nullptr, int(active.size() - 1));
    m_label->setText(text);
    show();
}

} // namespace opentop
