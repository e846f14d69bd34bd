#include "transport/SerialLineReport.h"

#include <QCoreApplication>
#include <QStringList>

namespace opentop {

namespace {

QString delayText(int us)
{
    return us % 1000 == 0
               ? QCoreApplication::translate("opentop::Transport", "%1 ms").arg(us / 1000)
               : QCoreApplication::translate("opentop::Transport", "%1 µs").arg(us);
}

} // namespace

QString SerialLineReport::text() const
{
    QStringList parts;
    for (const QString& part : {directionText(), lowLatencyText()})
        if (!part.isEmpty())
            parts << part;
    return parts.join(QStringLiteral("; "));
}

QString SerialLineReport::directionText() const
{
    QString how = rtsHighWhileSending
                      ? QCoreApplication::translate("opentop::Transport", "RTS high while sending")
                      : QCoreApplication::translate("opentop::Transport", "RTS low while sending");
    if (rtsDelayBeforeUs > 0 || rtsDelayAfterUs > 0)
        how += rtsDelayBeforeUs == rtsDelayAfterUs
                   ? QCoreApplication::translate("opentop::Transport", ", %1 before and after")
                         .arg(delayText(rtsDelayBeforeUs))
                   : QCoreApplication::translate("opentop::Transport", ", %1 before, %2 after")
                         .arg(delayText(rtsDelayBeforeUs), delayText(rtsDelayAfterUs));
    switch (direction) {
    case Direction::NotApplicable:
        return QString();
    case Direction::Adapter:
        return QCoreApplication::translate("opentop::Transport", "RS-485: switched by the adapter");
    case Direction::KernelLeftOn:
        return QCoreApplication::translate("opentop::Transport",
                                           "RS-485: kernel mode left on by the driver (%1)")
            .arg(how);
    case Direction::Kernel:
        return QCoreApplication::translate("opentop::Transport", "RS-485: kernel (%1)").arg(how);
    case Direction::Rts:
        if (!kernelRefusal.isEmpty())
            return QCoreApplication::translate(
                       "opentop::Transport",
                       "RS-485: RTS from the program (%1; kernel mode refused: %2)")
                .arg(how, kernelRefusal);
        return QCoreApplication::translate("opentop::Transport",
                                           "RS-485: RTS from the program (%1)")
            .arg(how);
    case Direction::Unavailable:
        if (!kernelRefusal.isEmpty() && !rtsRefusal.isEmpty())
            return QCoreApplication::translate(
                       "opentop::Transport",
                       "RS-485: not available (kernel mode refused: %1; RTS not switchable: %2)")
                .arg(kernelRefusal, rtsRefusal);
        if (!rtsRefusal.isEmpty())
            return QCoreApplication::translate("opentop::Transport",
                                               "RS-485: RTS not switchable on this port (%1)")
                .arg(rtsRefusal);
        return QCoreApplication::translate("opentop::Transport",
                                           "RS-485: kernel mode refused by the driver (%1)")
            .arg(kernelRefusal);
    }
    return QString();
}

QString SerialLineReport::lowLatencyText() const
{
    const QString timer = latencyTimerMs >= 0 ? QCoreApplication::translate("opentop::Transport",
                                                                            "latency timer %1 ms")
                                                    .arg(latencyTimerMs)
                                              : QString();
    switch (lowLatency) {
    case LowLatency::NotApplicable:
        return QString();
    case LowLatency::NotUart:
        return QCoreApplication::translate("opentop::Transport",
                                           "low latency: not a UART, no adapter latency");
    case LowLatency::On:
        if (latencyTimerMs > 1)
            return QCoreApplication::translate("opentop::Transport", "low latency: on (but %1)")
                .arg(timer);
        return QCoreApplication::translate("opentop::Transport", "low latency: on");
    case LowLatency::Unavailable:
#ifdef Q_OS_WIN // no program may set it there: the engineer does, once per adapter
        return QCoreApplication::translate("opentop::Transport",
                                           "low latency: the driver's setting (FTDI: Latency "
                                           "Timer 1 ms in Device Manager)");
#endif
        if (!timer.isEmpty())
            return QCoreApplication::translate("opentop::Transport",
                                               "low latency: not offered by the driver (%1)")
                .arg(timer);
        if (usbAdapter)
            return QCoreApplication::translate(
                       "opentop::Transport",
                       "low latency: not offered by the driver (USB adapter: up to %1 ms assumed)")
                .arg(kAssumedUsbLatencyMs);
        return QCoreApplication::translate("opentop::Transport",
                                           "low latency: not offered by the driver");
    case LowLatency::Off:
        return timer.isEmpty()
                   ? QCoreApplication::translate("opentop::Transport", "low latency: off")
                   : QCoreApplication::translate("opentop::Transport", "low latency: off (%1)")
                         .arg(timer);
    }
    return QString();
}

int SerialLineReport::adapterLatencyMs() const
{
    if (lowLatency == LowLatency::NotApplicable || lowLatency == LowLatency::NotUart)
        return 0;
    if (latencyTimerMs > 1)
        return latencyTimerMs; // what the adapter really does, whatever the flag says
    if (latencyTimerMs >= 0 || lowLatency == LowLatency::On)
        return 0;
    return usbAdapter ? kAssumedUsbLatencyMs : 0;
}

QString SerialLineReport::latencyWarning() const
{
    const int ms = adapterLatencyMs();
    if (ms <= 0)
        return QString();
    const QString why =
        lowLatency == LowLatency::Off
            ? QCoreApplication::translate("opentop::Transport", "low latency is off")
            : (lowLatency == LowLatency::On
                   ? QCoreApplication::translate(
                         "opentop::Transport",
                         "the driver took low latency but kept its latency timer")
                   : QCoreApplication::translate("opentop::Transport",
                                                 "the driver did not take low latency"));
    const QString fix = latencyTimerPath.isEmpty()
                            ? QCoreApplication::translate(
                                  "opentop::Transport",
                                  "see docs/hardware.md, or use an adapter whose driver offers "
                                  "low latency")
                            : QCoreApplication::translate(
                                  "opentop::Transport",
                                  "as root: echo 1 > %1, or the udev rule in docs/hardware.md")
                                  .arg(latencyTimerPath);
    return QCoreApplication::translate(
               "opentop::Transport",
               "The adapter holds received bytes for up to %1 ms before passing them on (%2). "
               "Fix: %3.")
        .arg(ms)
        .arg(why, fix);
}

} // namespace opentop
