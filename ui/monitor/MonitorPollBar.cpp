#include "ui/monitor/MonitorPollBar.h"

#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "ui/widgets/StaleLook.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

MonitorPollBar::MonitorPollBar(MonitorHub* hub, int slave, QWidget* parent)
    : QWidget(parent)
    , m_hub(hub)
    , m_slave(slave)
    , m_rate(new QComboBox(this))
    , m_pause(new QPushButton(this))
    , m_status(new QLabel(this))
{
    // The controls on one row, what they mean under them across the page's width: beside
    // them, the paused or lost-link sentence wrapped into three lines on a laptop.
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(0, 0, 0, 0);
    auto* bar = new QHBoxLayout;
    rows->addLayout(bar);
    bar->addWidget(new QLabel(tr("Poll every"), this));
    for (int hz : {1, 2, 5, 10, 20})
        m_rate->addItem(tr("%1 ms (%2 Hz)").arg(1000 / hz).arg(hz), 1000 / hz);
    m_rate->setToolTip(tr("How often every monitored drive is read. Commands you give always "
                          "go first; the drives share what is left of the bus in turn."));
    bar->addWidget(m_rate);
    bar->addWidget(m_pause);
    bar->addStretch(1);
    // Wrapped, not one line: a line as wide as the sentence widened the whole window past a
    // laptop's screen.
    m_status->setWordWrap(true);
    rows->addWidget(m_status);
    const auto showRate = [this](int ms) {
        const int i = m_rate->findData(ms);
        if (i < 0)
            m_rate->addItem(tr("%1 ms").arg(ms), ms);
        m_rate->setCurrentIndex(m_rate->findData(ms));
    };
    showRate(hub->interval());
    connect(hub, &MonitorHub::intervalChanged, this, showRate);
    connect(m_rate, &QComboBox::activated, this,
            [this] { m_hub->setInterval(m_rate->currentData().toInt()); });
    const auto showPaused = [this](bool paused) {
        m_pause->setText(paused ? tr("Resume polling") : tr("Pause polling"));
    };
    showPaused(hub->isPaused());
    connect(hub, &MonitorHub::pausedChanged, this, showPaused);
    connect(m_pause, &QPushButton::clicked, this, [this] { m_hub->setPaused(!m_hub->isPaused()); });
}

void MonitorPollBar::showFreshness(const StaleLook& look, const QString& lastError)
{
    const Freshness::State state = look.state();
    const bool stale = state == Freshness::State::Stale;
    QString text;
    if (m_hub->isPaused())
        text =
            tr("Polling paused: the values shown are the last ones read (%1).").arg(look.ageText());
    else if (m_hub->isHeld() && m_hub->drives()->linkUp())
        text = tr("Polling waits for the bus scan: %1.").arg(look.ageText());
    else if (!m_hub->drives()->linkUp())
        text = tr("Connection lost — not live: %1.").arg(look.ageText());
    else if (stale)
        text = lastError.isEmpty() ? tr("Not live: %1.").arg(look.ageText())
                                   : tr("The drive does not answer (%1) — not live: %2.")
                                         .arg(lastError, look.ageText());
    else if (state == Freshness::State::Live)
        text = tr("Values %1 · %2 samples/s")
                   .arg(look.ageText())
                   .arg(QLocale().toString(m_hub->statistics(m_slave).rate(), 'f', 1));
    else
        text = lastError.isEmpty() ? tr("Not read yet.")
                                   : tr("Cannot read the drive: %1").arg(lastError);
    if (m_status->text() != text)
        m_status->setText(text);
    const QString statusStyle = stale ? QStringLiteral("QLabel { color: #b01c1c; }") : QString();
    if (m_status->styleSheet() != statusStyle) // style sheets are costly to apply
        m_status->setStyleSheet(statusStyle);
}

QString MonitorPollBar::text() const
{
    return m_status->text();
}

} // namespace opentop
