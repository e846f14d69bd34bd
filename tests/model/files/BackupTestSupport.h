#pragma once

// An in-process bus with simulated drives for the backup, compare and restore tests: a DBU200
// at 1, a DBU400 at 150 and a DC controller at 7, every frame in a traffic log.

#include "model/files/BackupReader.h"
#include "model/files/Restorer.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "sim/SimBackend.h"
#include "sim/SimBus.h"
#include "tests/model/DriveSimFixture.h"
#include "transport/ModbusClient.h"
#include "transport/TrafficLog.h"

#include <QEventLoop>
#include <QTimer>
#include <gtest/gtest.h>
#include <memory>

namespace opentop::test {

class SimBusFixture : public DriveSimFixture
{
protected:
    void SetUp() override { startBus(QStringLiteral("dbu200@1,dbu400@150,dcpid@7"), 0, 50, 1); }

    static const Profile& profile(const char* family)
    {
        return *ProfileRegistry::builtIn().family(QString::fromLatin1(family));
    }

    template <typename Result, typename Start> Result waitFor(Start start)
    {
        return await<Result>(start, 10000);
    }

    BackupReader::Result backup(int slave)
    {
        BackupReader reader(session(slave));
        return waitFor<BackupReader::Result>([&](auto done) { reader.read(done); });
    }

    RestorePlan restore(Restorer& restorer, const BackupDevice& file, bool dryRun = false)
    {
        Restorer::Options options;
        options.dryRun = dryRun;
        return waitFor<RestorePlan>([&](auto done) { restorer.start(file, options, done); });
    }

    RestorePlan restore(int slave, const BackupDevice& file, bool dryRun = false)
    {
        Restorer restorer(session(slave));
        return restore(restorer, file, dryRun);
    }

    // A register as the simulated drive holds it (holding registers).
    int held(int slave, quint16 address)
    {
        const SimControlResult r =
            bus->control(slave, {QStringLiteral("get"),
                                 QStringLiteral("0x%1").arg(address, 4, 16, QLatin1Char('0'))});
        const QStringList words = r.text.split(QLatin1Char(' '));
        const int eq = int(words.indexOf(QStringLiteral("=")));
        return eq >= 0 ? words.value(eq + 1).toInt() : -1;
    }

    void set(int slave, quint16 address, int value)
    {
        const SimControlResult r =
            bus->control(slave, {QStringLiteral("set"),
                                 QStringLiteral("0x%1").arg(address, 4, 16, QLatin1Char('0')),
                                 QString::number(value)});
        ASSERT_TRUE(r.ok) << qPrintable(r.text);
    }

    int framesSent() const
    {
        int n = 0;
        for (const TrafficEntry& e : log.entries())
            n += e.direction == TrafficEntry::Direction::Tx ? 1 : 0;
        return n;
    }

    // Addresses of the write requests (06 and 10h) sent since entry `from`.
    QVector<quint16> writesSince(int from) const
    {
        QVector<quint16> addresses;
        const QVector<TrafficEntry> entries = log.entries();
        for (int i = from; i < entries.size(); ++i) {
            const TrafficEntry& e = entries.at(i);
            if (e.direction == TrafficEntry::Direction::Tx && (e.function == 6 || e.function == 16))
                addresses << quint16((quint8(e.bytes.at(2)) << 8) | quint8(e.bytes.at(3)));
        }
        return addresses;
    }

    int logSize() const { return int(log.entries().size()); }
};

} // namespace opentop::test
