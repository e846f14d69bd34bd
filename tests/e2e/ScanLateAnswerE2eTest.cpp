// The model's bus scanner over the real RTU backend against an opentop-sim process whose drives
// all answer 40 ms late, with a master that is busy between two addresses (the GUI's views take
// in each step). The late reply is then already waiting when the next address is asked, and the
// transport discards it; the scanner must still ask that drive again. The soak found the
// program's scan of 247 drives missing 2–23 of them this way.
#include "model/bus/BusScanner.h"
#include "model/profile/ProfileRegistry.h"
#include "tests/e2e/ScanToEnd.h"
#include "tests/e2e/SimProcess.h"
#include "transport/ModbusClient.h"
#include "transport/RtuBackend.h"

#include <QThread>
#include <gtest/gtest.h>

using namespace opentop;
using namespace opentop::test;

TEST(ScanLateAnswerE2e, ADriveWhoseLateReplyWasDiscardedIsAskedAgainAndFound)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@3,dcpid@5"),
                           QStringLiteral("--wire-timing"), QStringLiteral("--baud"),
                           QStringLiteral("19200"), QStringLiteral("--faults"),
                           QStringLiteral("late=1,late_ms=40"), QStringLiteral("--seed"),
                           QStringLiteral("1")},
                          &error))
        << error.toStdString();
    ConnectionSettings settings;
    settings.port = sim.pty;
    settings.baud = 19200;
    ModbusClient client(std::make_unique<RtuBackend>(settings), settings);
    ASSERT_TRUE(client.openBlocking().isEmpty());

    BusScanner scanner(&client, ProfileRegistry::builtIn());
    scanner.setRange(2, 6);
    scanner.setWaitMs(17);
    // A busy master: every step's views take 100 ms, longer than the reply is late.
    QObject::connect(&scanner, &BusScanner::progress, [] { QThread::msleep(100); });
    const QVector<DeviceInfo> devices = scanToEnd(scanner);

    ASSERT_EQ(devices.size(), 2);
    EXPECT_EQ(devices[0].slave, 3);
    EXPECT_EQ(devices[0].state, DeviceInfo::State::Present);
    EXPECT_TRUE(devices[0].detail.contains(QStringLiteral("answered late")))
        << devices[0].detail.toStdString();
    EXPECT_EQ(devices[1].slave, 5);
    EXPECT_EQ(devices[1].state, DeviceInfo::State::Present);
    EXPECT_EQ(scanner.lateAnswers(), 2);
}
