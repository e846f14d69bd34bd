#include "ui/widgets/StatusLight.h"

#include <QPainter>
#include <QPixmap>
#include <algorithm>

namespace opentop {

namespace {

void paintLed(QPainter& p, const QRectF& box, const QColor& c)
{
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(c.darker(160), 1.0));
    // A light spot at the top left makes it read as a lamp, not a flat dot.
    QRadialGradient g(box.center() - QPointF(box.width() / 5, box.height() / 5), box.width() / 1.5);
    g.setColorAt(0, c.lighter(150));
    g.setColorAt(1, c);
    p.setBrush(g);
    p.drawEllipse(box.adjusted(0.5, 0.5, -0.5, -0.5));
}

} // namespace

StatusLight::StatusLight(QWidget* parent)
    : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    setFocusPolicy(Qt::NoFocus);
    setLed(DriveStatus::Led::Grey, tr("Status not known yet"));
}

void StatusLight::setStatus(const DriveStatus& status)
{
    setLed(status.led, status.ledText(), status.ledEntry ? &*status.ledEntry : nullptr);
}

void StatusLight::setLed(DriveStatus::Led led, const QString& meaning, const StatusLedEntry* entry)
{
    m_led = led;
    m_meaning = meaning;
    const QColor colour = entry ? QColor(entry->colour) : color(led);
    QString text =
        tr("Status light %1: %2").arg(entry ? entry->label : DriveStatus::ledName(led), meaning);
    if (entry) {
        DriveStatus manual;
        manual.ledEntry = *entry;
        text += QLatin1Char('\n') + tr("The drive's manual: %1").arg(manual.ledManualText());
    }
    // Every sample sets the light: repainted and announced only when it changes.
    if (colour == m_color && text == toolTip())
        return;
    m_color = colour;
    setToolTip(text);
    setAccessibleName(text);
    update();
}

QSize StatusLight::sizeHint() const
{
    // Follows the font so that it scales with the user's text size and the screen.
    const int d = fontMetrics().height();
    return {d, d};
}

QSize StatusLight::minimumSizeHint() const
{
    return {8, 8};
}

QColor StatusLight::color(DriveStatus::Led led)
{
    switch (led) {
    case DriveStatus::Led::Grey:
        return QColor(0x9e, 0x9e, 0x9e);
    case DriveStatus::Led::Green:
        return QColor(0x2e, 0xb8, 0x3c);
    case DriveStatus::Led::Orange:
        return QColor(0xff, 0x8c, 0x00);
    case DriveStatus::Led::SkyBlue:
        return QColor(0x4f, 0xc3, 0xf7);
    case DriveStatus::Led::Red:
        return QColor(0xe5, 0x1c, 0x23);
    case DriveStatus::Led::Purple:
        return QColor(0x9c, 0x27, 0xb0);
    case DriveStatus::Led::Blue:
        return QColor(0x15, 0x4d, 0xd6);
    }
    return Qt::gray;
}

QColor StatusLight::color(const DriveStatus& status, DriveStatus::Led shown)
{
    if (status.ledEntry && shown == status.led)
        return QColor(status.ledEntry->colour);
    return color(shown);
}

QPixmap StatusLight::pixmap(const QColor& color, int size, qreal devicePixelRatio)
{
    QPixmap pm(QSize(size, size) * devicePixelRatio);
    pm.setDevicePixelRatio(devicePixelRatio);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    paintLed(p, QRectF(0, 0, size, size), color);
    return pm;
}

void StatusLight::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    const qreal d = std::min(width(), height());
    paintLed(p, QRectF((width() - d) / 2, (height() - d) / 2, d, d), m_color);
}

} // namespace opentop
