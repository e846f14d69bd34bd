#pragma once

// An in-process simulated bus with sessions and helpers to wait for asynchronous engines, for
// the monitor, alarm history and run control tests.

#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "sim/SimBackend.h"
#include "sim/SimBus.h"
#include "transport/ModbusClient.h"
#include "transport/TrafficLog.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <functional>
#include <gtest/gtest.h>
#include <map>
#include <memory>

namespace opentop::test {

class DriveSimFixture : public ::testing::Test
{
protected:
    // `spec` as on the command line; wire timing at `baud` when > 0.
    void startBus(const QString& spec, int wireBaud = 0, int timeoutMs = 100, int retries = 0)
    {
        QString error;
        bus = SimBus::fromSpec(spec, &error);
        ASSERT_TRUE(bus) << qPrintable(error);
        auto backend =
            std::make_unique<SimBackend>(bus, wireBaud > 0, wireBaud > 0 ? wireBaud : 19200);
        backend->setTrafficLog(&log);
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.simSpec = bus->spec();
        settings.timeoutMs = timeoutMs;
        settings.retries = retries;
        client = std::make_unique<ModbusClient>(std::move(backend), settings);
        ASSERT_TRUE(client->openBlocking().isEmpty());
    }

    void TearDown() override
    {
        sessions.clear();
        client.reset();
    }

    DeviceSession* session(int slave)
    {
        auto& s = sessions[slave];
        if (!s) {
            SimDevice* device = bus->device(slave);
            const Profile* profile = device
                                         ? &device->profile()
                                         : ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
            const Profile* builtIn = ProfileRegistry::builtIn().family(profile->family);
            s = std::make_unique<DeviceSession>(client.get(), *builtIn, slave,
                                                device ? device->variant() : QString());
        }
        return s.get();
    }

    // A BusDrives over this bus's client with `slaves` identified as the simulator has them:
    // family and variant, the variant in capitals (or the family's) as the model.
    std::unique_ptr<BusDrives> identifiedDrives(const QVector<int>& slaves)
    {
        auto drives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
        for (int slave : slaves) {
            SimDevice* device = bus->device(slave);
            EXPECT_TRUE(device) << "no simulated drive at " << slave;
            if (!device)
                continue;
            DeviceInfo info;
            info.slave = slave;
            info.state = DeviceInfo::State::Present;
            info.family = device->profile().family;
            info.variant = device->variant();
            info.model = (info.variant.isEmpty() ? info.family : info.variant).toUpper();
            drives->update(info);
        }
        return drives;
    }

    // Runs `start`, which must call the callback it gets, and returns what it delivered.
    template <typename T>
    T await(const std::function<void(std::function<void(const T&)>)>& start, int timeoutMs = 15000)
    {
        T result{};
        bool finished = false;
        QEventLoop loop;
        start([&](const T& r) {
            result = r;
            finished = true;
            loop.quit();
        });
        if (!finished) {
            QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
            loop.exec();
        }
        EXPECT_TRUE(finished) << "no answer within " << timeoutMs << " ms";
        return result;
    }

    // Processes events until `done` holds or the time is up.
    bool waitUntil(const std::function<bool()>& done, int timeoutMs = 5000)
    {
        QElapsedTimer timer;
        timer.start();
        while (!done()) {
            if (timer.elapsed() > timeoutMs)
                return false;
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        }
        return true;
    }

    void control(int slave, const QStringList& args)
    {
        const SimControlResult r = bus->control(slave, args);
        ASSERT_TRUE(r.ok) << qPrintable(r.text);
    }

    // core.control_priority = communication, through the simulator's backdoor.
    void communicationPriority(int slave)
    {
        control(slave, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    }

    int framesSent(quint8 function = 0) const
    {
        int n = 0;
        for (const TrafficEntry& e : log.entries())
            n += e.direction == TrafficEntry::Direction::Tx && (!function || e.function == function)
                     ? 1
                     : 0;
        return n;
    }

    TrafficLog log;
    std::shared_ptr<SimBus> bus;
    std::unique_ptr<ModbusClient> client;
    std::map<int, std::unique_ptr<DeviceSession>> sessions;
};

} // namespace opentop::test
