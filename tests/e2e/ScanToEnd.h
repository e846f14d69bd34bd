// Runs a bus scan to its end in a local event loop, as the e2e tests over a pty need it.
#pragma once
#include "model/bus/BusScanner.h"

#include <QEventLoop>
#include <QTimer>

namespace opentop::test {

// Starts `scanner` and returns what it found; empty when it did not finish within `timeoutMs`.
inline QVector<DeviceInfo> scanToEnd(BusScanner& scanner, int timeoutMs = 30000)
{
    QVector<DeviceInfo> devices;
    QEventLoop loop;
    QObject::connect(&scanner, &BusScanner::finished, &loop, [&](const QVector<DeviceInfo>& found) {
        devices = found;
        loop.quit();
    });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    scanner.start();
    loop.exec();
    return devices;
}

} // namespace opentop::test
