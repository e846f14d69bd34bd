#pragma once

// Widget tests against an in-process simulated bus: the model fixture plus helpers to wait for
// a page's asynchronous refresh/write and to read a simulated register.

#include "tests/model/DriveSimFixture.h"

#include <QRegularExpression>

namespace opentop::test {

class UiSimFixture : public DriveSimFixture
{
protected:
    // Runs `start` and waits until `object` emits `signal`.
    template <typename Object, typename Signal>
    bool runUntil(Object* object, Signal signal, const std::function<void()>& start)
    {
        bool emitted = false;
        const QMetaObject::Connection c =
            QObject::connect(object, signal, object, [&emitted] { emitted = true; });
        start();
        const bool ok = waitUntil([&emitted] { return emitted; }, 15000);
        QObject::disconnect(c);
        return ok;
    }

    // The raw value of a holding register of a simulated device.
    int simRegister(int slave, quint16 address)
    {
        const SimControlResult r =
            bus->control(slave, {QStringLiteral("get"),
                                 QStringLiteral("0x%1").arg(address, 4, 16, QLatin1Char('0'))});
        EXPECT_TRUE(r.ok) << qPrintable(r.text);
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("= (\\d+) ")).match(r.text);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }

    int writesSent() const { return framesSent(6) + framesSent(16); }
};

} // namespace opentop::test
