#pragma once

#include "model/bus/DriveStatusPoller.h"

#include <QColor>
#include <QWidget>

namespace opentop {

// A small round LED in a drive's MONITOR colour. What the colour means is in the tooltip and
// the accessible name, so that it is never told by colour alone.
class StatusLight : public QWidget
{
    Q_OBJECT
public:
    explicit StatusLight(QWidget* parent = nullptr);

    void setStatus(const DriveStatus& status);
    // `entry`: the profile's light (colour, name, the manual's meaning); nullptr: the program's.
    void setLed(DriveStatus::Led led, const QString& meaning,
                const StatusLedEntry* entry = nullptr);
    DriveStatus::Led led() const { return m_led; }
    QString meaning() const { return m_meaning; }
    QColor shownColor() const { return m_color; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

    // The program's own colour for `led`, for families whose profile has no status LED table.
    static QColor color(DriveStatus::Led led);
    // The colour a status's light is painted in: the profile's (DriveStatus::ledEntry) while
    // `shown` is the status's own light, otherwise the program's.
    static QColor color(const DriveStatus& status, DriveStatus::Led shown);
    // A round icon of `color` in `size` device-independent pixels, for item views.
    static QPixmap pixmap(const QColor& color, int size, qreal devicePixelRatio);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    DriveStatus::Led m_led = DriveStatus::Led::Grey;
    QString m_meaning;
    QColor m_color;
};

} // namespace opentop
