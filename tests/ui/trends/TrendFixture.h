#pragma once

// Trend chart tests: two simulated DBU drives on a BusDrives with a MonitorHub polling fast.

#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "tests/ui/UiSimFixture.h"

namespace opentop::test {

class TrendFixture : public UiSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1,dbu200@2"));
        drives = identifiedDrives({1, 2});
        hub = std::make_unique<MonitorHub>(drives.get());
        hub->setInterval(50);
    }

    void TearDown() override
    {
        hub.reset();
        drives.reset();
        UiSimFixture::TearDown();
    }

    // Runs the motor in I/O priority (X0 = CW/STOP) at the Ext-VR's `rpm`: SPno1 ramps over
    // about rpm / 3000 seconds.
    void startMotor(int slave, int rpm = 3000)
    {
        control(slave, {QStringLiteral("vr"), QString::number(rpm)});
        control(slave, {QStringLiteral("input"), QStringLiteral("1")});
    }

    const TrendHistory::Series* series(int slave, const char* key) const
    {
        const TrendHistory* h = hub->history(slave);
        return h ? h->find(QLatin1String(key)) : nullptr;
    }

    int pointCount(int slave, const char* key) const
    {
        const TrendHistory::Series* s = series(slave, key);
        return s ? int(s->points.size()) : 0;
    }

    double lastValue(int slave, const char* key) const
    {
        const TrendHistory::Series* s = series(slave, key);
        return s && !s->points.isEmpty() ? s->points.last().value : 0;
    }

    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<MonitorHub> hub;
};

} // namespace opentop::test
