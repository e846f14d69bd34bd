#include "ui/monitor/PanelMirrorView.h"

#include "ui/widgets/StaleLook.h"
#include "ui/widgets/StatusLight.h"

#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>

namespace opentop {

PanelMirrorView::PanelMirrorView(QWidget* parent)
    : QWidget(parent)
    , m_panel(new QLabel(this))
    , m_meaning(new QLabel(this))
    , m_content(new QLabel(this))
    , m_light(new StatusLight(this))
{
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    auto* title = new QLabel(tr("Drive panel"), this);
    QFont bold = title->font();
    bold.setBold(true);
    title->setFont(bold);
    grid->addWidget(title, 0, 0, 1, 2);
    m_panel->setObjectName(QStringLiteral("panelDigits"));
    QFont digits = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    digits.setBold(true);
    digits.setPointSizeF(title->font().pointSizeF() * 2.6);
    m_panel->setFont(digits);
    m_panel->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_panel->setMinimumWidth(QFontMetrics(digits).horizontalAdvance(QStringLiteral("-8888.8")) +
                             24);
    m_panel->setContentsMargins(12, 4, 12, 4);
    grid->addWidget(m_panel, 1, 0);
    m_light->setMinimumSize(24, 24);
    m_light->setFixedSize(m_panel->sizeHint().height() / 2, m_panel->sizeHint().height() / 2);
    grid->addWidget(m_light, 1, 1, Qt::AlignCenter);
    m_meaning->setWordWrap(true);
    grid->addWidget(m_meaning, 2, 0, 1, 2);
    m_content->setEnabled(false); // secondary information
    m_content->setWordWrap(true);
    grid->addWidget(m_content, 3, 0, 1, 2);
    grid->setColumnStretch(0, 1);
    // The drive flashes an alarm code; so does its mirror (twice a second).
    m_blink.setInterval(500);
    connect(&m_blink, &QTimer::timeout, this, [this] {
        m_blinkOn = !m_blinkOn;
        paintPanel();
    });
    setShown(PanelMirror::Shown{QStringLiteral("-----"), false, false, tr("Not read yet")},
             QString());
}

void PanelMirrorView::setShown(const PanelMirror::Shown& shown, const QString& contentName)
{
    m_shown = shown;
    if (shown.alarm && !m_blink.isActive())
        m_blink.start();
    else if (!shown.alarm) {
        m_blink.stop();
        m_blinkOn = true;
    }
    m_meaning->setText(shown.overflow ? tr("%1 (more digits than the panel has)").arg(shown.meaning)
                                      : shown.meaning);
    m_content->setText(contentName.isEmpty()
                           ? QString()
                           : tr("Panel set to show the %1 while running.").arg(contentName));
    const QString name = tr("Drive panel shows %1").arg(shown.text);
    if (name != m_panel->accessibleName()) { // every sample: announced only when it changes
        m_panel->setAccessibleName(name);
        m_panel->setToolTip(name);
    }
    paintPanel();
}

void PanelMirrorView::setStale(bool stale, const QString& why)
{
    if (stale)
        m_light->setLed(DriveStatus::Led::Grey, why.isEmpty() ? tr("not live") : why);
    if (stale == m_stale)
        return;
    m_stale = stale;
    StaleLook::apply(this, stale);
    m_lit.reset();
    paintPanel();
}

QString PanelMirrorView::meaningText() const
{
    return m_meaning->text();
}

void PanelMirrorView::paintPanel()
{
    // Segment displays: red digits on black; an alarm flashes.
    // Stale: the last digits read, grey and steady (a mirror that flashes looks alive).
    const bool lit = m_stale || !m_shown.alarm || m_blinkOn;
    m_panel->setText(m_shown.text);
    if (m_lit == lit)
        return; // style sheets are costly to apply
    m_lit = lit;
    const QString color = m_stale ? QStringLiteral("#777777")
                                  : (lit ? QStringLiteral("#ff3b30") : QStringLiteral("#3a0d0b"));
    m_panel->setStyleSheet(
        QStringLiteral("QLabel#panelDigits { background: #111; color: %1; border-radius: 6px; }")
            .arg(color));
}

} // namespace opentop
