#include "ui/main/ConnectionStatus.h"

#include "transport/SerialLineReport.h"
#include "ui/widgets/StatusLight.h"

#include <QLabel>
#include <QMainWindow>
#include <QStatusBar>

namespace opentop {

ConnectionStatus::ConnectionStatus(QMainWindow* window)
    : QObject(window)
    , m_label(new QLabel(window))
    , m_light(new StatusLight(window))
    , m_simBanner(new QLabel(window))
{
    // A simulated bus is unmistakable: a permanent coloured marker in the status bar (and the
    // window title) say so; it costs no height on a laptop screen.
    m_simBanner->setObjectName(QStringLiteral("simulatedBanner"));
    m_simBanner->setText(tr("SIMULATED BUS — no hardware"));
    m_simBanner->setToolTip(tr("These drives exist only in this program; nothing moves."));
    m_simBanner->setStyleSheet(QStringLiteral("background: #f9a825; color: black; "
                                              "font-weight: bold; padding: 0 8px;"));
    m_simBanner->hide();
    m_light->setObjectName(QStringLiteral("linkLight"));
    m_light->setLed(DriveStatus::Led::Grey, tr("Not connected"));
}

void ConnectionStatus::showIn(QStatusBar* bar)
{
    bar->addPermanentWidget(m_simBanner);
    bar->addPermanentWidget(m_light);
    bar->addPermanentWidget(m_label);
}

void ConnectionStatus::setText(const QString& text, bool problem)
{
    // A port error can be several long lines: the status bar shows the first, shortened, so
    // that it never widens the window; the whole text is in the tooltip.
    const QString first = text.section(QLatin1Char('\n'), 0, 0);
    // Measured in the font it will have: a problem is shown bold (the style sheet below).
    QFont font = m_label->font();
    font.setBold(problem);
    m_label->setText(QFontMetrics(font).elidedText(first, Qt::ElideRight, 520));
    m_label->setToolTip(text);
    m_label->setStyleSheet(problem ? QStringLiteral("color: white; background: #b01c1c; "
                                                    "font-weight: bold; padding: 0 6px;")
                                   : QString());
}

void ConnectionStatus::setConnected(const QString& description, const SerialLineReport& report)
{
    QString text = tr("Connected: %1").arg(description);
    if (!report.isEmpty())
        text += tr(" — %1").arg(report.text());
    const QString warning = report.latencyWarning();
    if (!warning.isEmpty())
        text += QLatin1Char('\n') + warning;
    setText(text, report.direction == SerialLineReport::Direction::Unavailable);
}

void ConnectionStatus::setLinkUp(bool up, const QString& why)
{
    m_light->setLed(up ? DriveStatus::Led::Green : DriveStatus::Led::Grey, why);
}

void ConnectionStatus::setSimulated(bool simulated)
{
    m_simBanner->setVisible(simulated);
}

void ConnectionStatus::reset()
{
    m_simBanner->hide();
    m_light->setLed(DriveStatus::Led::Grey, tr("Not connected"));
}

} // namespace opentop
