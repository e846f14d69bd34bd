#pragma once

#include "bus/DriveStatusPoller.h"

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
    void setLed(DriveStatus::Led led, const QString& meaning);
    DriveStatus::Led led() const { return m_led; }
    QString meaning() const { return m_meaning; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

    // The colour painted for `led` (also used by the bus list's delegate-free decoration).
    static QColor color(DriveStatus::Led led);
    // A round icon of `led` in `size` device-independent pixels, for item views.
    static QPixmap pixmap(DriveStatus::Led led, int size, qreal devicePixelRatio);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    DriveStatus::Led m_led = DriveStatus::Led::Grey;
    QString m_meaning;
};

} // namespace opentop
