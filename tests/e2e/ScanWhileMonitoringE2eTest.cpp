// Issue 24, item 3: a scan while a drive is monitored, on a half-duplex line with wire timing.
// The model's scanner, monitor hub and status poller over the real RTU backend against an
// opentop-sim process: every family (DBU200, DBU400, DC controller) at 9600, 19200 and 115200
// bit/s, with placements and answer delays drawn from seeded generators. The DC controller's
// 25-byte identification reply is still on the wire when the first-byte wait ends; a poll sent
// then destroyed it and the scan lost the controller. Every drive must be found every time.
#include "model/bus/BusDrives.h"
#include "model/bus/BusScanner.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/monitor/MonitorHub.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceIdentifier.h"
#include "tests/e2e/ScanToEnd.h"
#include "tests/e2e/SimProcess.h"
#include "transport/ModbusClient.h"
#include "transport/RtuBackend.h"

#include <QEventLoop>
#include <QRandomGenerator>
#include <QTimer>
#include <gtest/gtest.h>

using namespace opentop;
using namespace opentop::test;

namespace {

struct Placement
{
    QString type;
    int slave = 0;
    int turnaroundMs = 0;
};

// Three drives, one of each family, at distinct machine numbers of 1..`last`, each answering
// 0–14 ms after the gap (the DBU manual's T3 10 ms + C1 up to 4 ms).
QVector<Placement> place(quint32 seed, int last)
{
    QRandomGenerator random(seed);
    QVector<Placement> drives;
    for (const char* type : {"dbu200", "dbu400", "dcpid"}) {
        Placement p;
        p.type = QString::fromLatin1(type);
        do
            p.slave = 1 + int(random.bounded(last));
        while (std::any_of(drives.begin(), drives.end(),
                           [&p](const Placement& d) { return d.slave == p.slave; }));
        p.turnaroundMs = int(random.bounded(15));
        drives << p;
    }
    return drives;
}

QString spec(const QVector<Placement>& drives)
{
    QStringList items;
    for (const Placement& d : drives)
        items
            << QStringLiteral("%1@%2{turnaround=%3}").arg(d.type).arg(d.slave).arg(d.turnaroundMs);
    return items.join(QLatin1Char(','));
}

DeviceInfo identify(ModbusClient& client, int slave)
{
    DeviceIdentifier identifier(&client, ProfileRegistry::builtIn());
    DeviceInfo info;
    QEventLoop loop;
    identifier.identify(slave, [&](const DeviceInfo& i) {
        info = i;
        loop.quit();
    });
    QTimer::singleShot(10000, &loop, &QEventLoop::quit);
    loop.exec();
    return info;
}

// One scan of 1..`last` at `baud` while the drive `monitored` is polled by the monitor hub (as
// the Monitor page does) and the status poller (as the bus list does); returns what the scan
// says about every drive placed in that range, as "slave:family" or "slave:MISSING".
QStringList scanWhileMonitoring(const QVector<Placement>& drives, int baud, quint32 seed, int last,
                                int monitored, QString* error)
{
    SimProcess sim;
    if (!sim.start({QStringLiteral("--devices"), spec(drives), QStringLiteral("--wire-timing"),
                    QStringLiteral("--half-duplex"), QStringLiteral("--baud"),
                    QString::number(baud), QStringLiteral("--seed"), QString::number(seed)},
                   error))
        return {};
    ConnectionSettings settings;
    settings.port = sim.pty;
    settings.baud = baud;
    ModbusClient client(std::make_unique<RtuBackend>(settings), settings);
    if (const QString failed = client.openBlocking(); !failed.isEmpty()) {
        *error = failed;
        return {};
    }
    BusDrives bus(&client, ProfileRegistry::builtIn());
    const DeviceInfo known = identify(client, monitored);
    if (known.state != DeviceInfo::State::Present) {
        *error = QStringLiteral("the monitored drive %1 was not identified: %2")
                     .arg(monitored)
                     .arg(known.detail);
        return {};
    }
    bus.update(known);
    MonitorHub hub(&bus);
    hub.setInterval(100); // 10 Hz, the page's fastest common choice
    QObject watcher;
    hub.watch(monitored, &watcher);
    DriveStatusPoller poller(&bus);
    poller.setInterval(250);
    poller.start();
    // Polling is under way when the scan starts, as in the window.
    QEventLoop settle;
    QObject::connect(&hub, &MonitorHub::sample, &settle, &QEventLoop::quit);
    QTimer::singleShot(10000, &settle, &QEventLoop::quit);
    settle.exec();
    if (!hub.latest(monitored)) {
        *error = QStringLiteral("no sample of drive %1 before the scan").arg(monitored);
        return {};
    }
    const qint64 samplesBefore = hub.statistics(monitored).samples;

    BusScanner scanner(&client, ProfileRegistry::builtIn());
    scanner.setRange(1, last);
    const QVector<DeviceInfo> found = scanToEnd(scanner, 60000);

    QStringList result;
    for (const Placement& p : drives) {
        if (p.slave > last)
            continue;
        const auto it = std::find_if(found.begin(), found.end(),
                                     [&p](const DeviceInfo& d) { return d.slave == p.slave; });
        if (it == found.end() || it->state != DeviceInfo::State::Present)
            result << QStringLiteral("%1:MISSING").arg(p.slave);
        else
            result << QStringLiteral("%1:%2").arg(p.slave).arg(it->family);
    }
    // Monitoring goes on after the scan.
    QEventLoop after;
    QTimer::singleShot(500, &after, &QEventLoop::quit);
    after.exec();
    const MonitorHub::Statistics stats = hub.statistics(monitored);
    if (stats.samples <= samplesBefore)
        *error = QStringLiteral("monitoring did not go on after the scan at %1 bit/s: %2 samples "
                                "before, %3 after, %4 errors, %5 in a row, held %6")
                     .arg(baud)
                     .arg(samplesBefore)
                     .arg(stats.samples)
                     .arg(stats.errors)
                     .arg(stats.errorsInRow)
                     .arg(client.isPollingHeld());
    return result;
}

QStringList expected(const QVector<Placement>& drives)
{
    QStringList list;
    for (const Placement& p : drives)
        list << QStringLiteral("%1:%2").arg(p.slave).arg(
            p.type == QLatin1String("dcpid") ? QStringLiteral("dcpid") : QStringLiteral("dbu"));
    return list;
}

} // namespace

class ScanWhileMonitoringE2e : public ::testing::TestWithParam<int>
{
};

TEST_P(ScanWhileMonitoringE2e, EveryDriveOfEveryFamilyIsFoundAtEverySeed)
{
    const int baud = GetParam();
    for (quint32 seed : {1u, 2u, 3u}) {
        const QVector<Placement> drives = place(seed * 7919u + quint32(baud), 24);
        const int monitored = drives[int(seed % 3)].slave;
        QString error;
        const QStringList found = scanWhileMonitoring(drives, baud, seed, 24, monitored, &error);
        EXPECT_TRUE(error.isEmpty()) << "seed " << seed << ": " << qPrintable(error);
        EXPECT_EQ(found, expected(drives))
            << "seed " << seed << ", " << baud << " bit/s, bus " << qPrintable(spec(drives))
            << ", monitoring " << monitored;
    }
}

INSTANTIATE_TEST_SUITE_P(Bauds, ScanWhileMonitoringE2e, ::testing::Values(9600, 19200, 115200),
                         [](const ::testing::TestParamInfo<int>& baud) {
                             return QStringLiteral("At%1").arg(baud.param).toStdString();
                         });

// The case the issue reports, as it was seen: drive 1 monitored, the DC controller at 7.
TEST(ScanWhileMonitoringE2e, TheDcControllerIsFoundWhileDrive1IsMonitored)
{
    const QVector<Placement> drives = {{QStringLiteral("dbu200"), 1, 2},
                                       {QStringLiteral("dbu400"), 150, 2},
                                       {QStringLiteral("dcpid"), 7, 2}};
    for (int baud : {9600, 19200}) {
        QString error;
        const QStringList found = scanWhileMonitoring(drives, baud, 1, 10, 1, &error);
        EXPECT_TRUE(error.isEmpty()) << qPrintable(error);
        EXPECT_EQ(found, (QStringList{QStringLiteral("1:dbu"), QStringLiteral("7:dcpid")}))
            << baud << " bit/s";
    }
}
