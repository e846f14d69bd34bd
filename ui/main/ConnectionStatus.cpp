#include "main/ConnectionStatus.h"

#include "widgets/StatusLight.h"

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
    m_label->setText(m_label->fontMetrics().elidedText(first, Qt::ElideRight, 520));
    m_label->setToolTip(text);
    m_label->setStyleSheet(problem ? QStringLiteral("color: white; background: #b01c1c; "
                                                    "font-weight: bold; padding: 0 6px;")
                                   : QString());
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
