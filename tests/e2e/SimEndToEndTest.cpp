// opentop-sim as a separate process on a pty (and TCP), driven through the project's libmodbus
// backends and the bus client: reads, writes, exceptions, broadcast, identification, faults,
// wire timing, console, shutdown.
#include "tests/e2e/SimProcess.h"

#include "transport/ConnectionSettings.h"
#include "transport/DeviceIdentification.h"
#include "transport/ModbusClient.h"
#include "transport/ModbusRequest.h"
#include "transport/RtuBackend.h"
#include "transport/TcpBackend.h"

#include <QFileInfo>
#include <QTemporaryDir>
#include <QThread>

using namespace opentop;
using namespace opentop::test;

namespace {

std::unique_ptr<ModbusClient> rtuClient(const QString& port, int timeoutMs = 300, int baud = 19200)
{
    ConnectionSettings s;
    s.kind = ConnectionSettings::Kind::Serial;
    s.port = port;
    s.baud = baud;
    s.parity = 'N';
    s.timeoutMs = timeoutMs;
    s.retries = 0;
    auto client = std::make_unique<ModbusClient>(std::make_unique<RtuBackend>(s), s);
    const QString error = client->openBlocking();
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    return client;
}

} // namespace

TEST(SimEndToEnd, ReadsWritesAndExceptionsOverThePty)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(
        sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dcpid@7")}, &error))
        << error.toStdString();
    ASSERT_TRUE(sim.pty.startsWith(QLatin1String("/dev/pts/"))) << sim.pty.toStdString();
    auto client = rtuClient(sim.pty);

    ModbusResult r = client->execute(ModbusRequest::readHolding(1, 0xCA03, 1));
    ASSERT_TRUE(r.ok()) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, (QVector<quint16>{1000}));

    ASSERT_TRUE(client->execute(ModbusRequest::writeSingle(1, 0xCA03, 1500)).ok());
    EXPECT_EQ(sim.get(1, 0xCA03), 1500);
    ASSERT_TRUE(client->execute(ModbusRequest::writeMultiple(1, 0x0403, {0, 250})).ok());
    EXPECT_EQ(sim.get(1, 0x0404), 250);

    r = client->execute(ModbusRequest::writeSingle(1, 0x007B, 10));
    EXPECT_EQ(r.error, ModbusError::Exception);
    EXPECT_EQ(r.exceptionCode, 0x02);
    r = client->execute(ModbusRequest::readInput(1, 0x007B, 1));
    EXPECT_EQ(r.registers, (QVector<quint16>{0xE0}));
    r = client->execute(ModbusRequest::writeSingle(1, 0xCA03, 100));
    EXPECT_EQ(r.exceptionCode, 0x04);
    EXPECT_EQ(client->execute(ModbusRequest::readInput(1, 0x007B, 1)).registers.value(0), 0xE8);

    r = client->execute(ModbusRequest::writeSingle(7, 0x0040, 1001));
    EXPECT_EQ(r.exceptionCode, 0x03);
    r = client->execute(ModbusRequest::readHolding(9, 0x0000, 1)); // nobody there
    EXPECT_EQ(r.error, ModbusError::Timeout);
    // The line is usable again after the timeout.
    EXPECT_TRUE(client->execute(ModbusRequest::readHolding(7, 0x0010, 3)).ok());
}

TEST(SimEndToEnd, BroadcastAndMotion)
{
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dbu400@2")}));
    auto client = rtuClient(sim.pty);
    ASSERT_TRUE(client->execute(ModbusRequest::writeSingle(0, 0x100D, 2)).ok()); // priority
    ASSERT_TRUE(client->execute(ModbusRequest::writeSingle(0, 0xCA03, 1200)).ok());
    EXPECT_EQ(sim.get(1, 0xCA03), 1200);
    EXPECT_EQ(sim.get(2, 0xCA03), 1200);
    EXPECT_EQ(sim.get(2, 0x100D), 2);
    ASSERT_TRUE(client->execute(ModbusRequest::writeSingle(0, 0x200F, 1)).ok()); // SPno2
    ASSERT_TRUE(client->execute(ModbusRequest::writeSingle(0, 0x2003, 1)).ok()); // START
    QThread::msleep(500); // 0.5 s ramps: 1200 r/min after 0.2 s
    const ModbusResult r = client->execute(ModbusRequest::readInput(2, 0x0107, 3));
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.registers.value(0), 1200); // target
    EXPECT_EQ(r.registers.value(2), 1200); // current
    EXPECT_EQ(sim.get(1, 0x0109), 1200);
    ASSERT_TRUE(client->execute(ModbusRequest::writeSingle(0, 0x2003, 0)).ok());
    QThread::msleep(400);
    EXPECT_EQ(client->execute(ModbusRequest::readInput(1, 0x0109, 1)).registers.value(0), 0);
}

TEST(SimEndToEnd, DeviceIdentificationOfTheDcController)
{
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dcpid@7")}));
    auto client = rtuClient(sim.pty);
    const ModbusResult r = client->execute(ModbusRequest::readDeviceIdentification(7));
    ASSERT_TRUE(r.ok()) << r.errorText().toStdString();
    DeviceIdentification id;
    ASSERT_TRUE(DeviceIdentification::parse(r.rawData, &id));
    EXPECT_EQ(id.text(1), QStringLiteral("DCPID-20A"));
    EXPECT_EQ(id.text(2), QStringLiteral("V1.0"));
}

TEST(SimEndToEnd, BusyAndDropFaults)
{
    SimProcess busy;
    ASSERT_TRUE(busy.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                            QStringLiteral("--faults"), QStringLiteral("busy=1")}));
    auto client = rtuClient(busy.pty);
    ModbusResult r = client->execute(ModbusRequest::writeSingle(1, 0xCA03, 1500));
    EXPECT_EQ(r.exceptionCode, 0x04);
    EXPECT_EQ(busy.get(1, 0xCA03), 1000); // not executed
    EXPECT_EQ(busy.get(1, 0x007B), 0xE3);
    client.reset();

    // The same seed gives the same faults.
    QVector<bool> runs[2];
    for (QVector<bool>& outcome : runs) {
        SimProcess drop;
        ASSERT_TRUE(drop.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                                QStringLiteral("--faults"), QStringLiteral("drop=0.5"),
                                QStringLiteral("--seed"), QStringLiteral("11")}));
        auto c = rtuClient(drop.pty, 100);
        for (int i = 0; i < 10; ++i)
            outcome << c->execute(ModbusRequest::readHolding(1, 0xCA03, 1)).ok();
    }
    EXPECT_EQ(runs[0], runs[1]);
    EXPECT_TRUE(runs[0].contains(true));
    EXPECT_TRUE(runs[0].contains(false));
}

TEST(SimEndToEnd, WireTimingDelaysReplies)
{
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                           QStringLiteral("--wire-timing"), QStringLiteral("--baud"),
                           QStringLiteral("9600")}));
    auto client = rtuClient(sim.pty, 300, 9600);
    const ModbusResult r = client->execute(ModbusRequest::readHolding(1, 0xCA03, 1));
    ASSERT_TRUE(r.ok()) << r.errorText().toStdString();
    // 8 + 7 characters at 9600 bit/s, 3.5 characters gap, 2 ms turnaround: 21.3 ms.
    EXPECT_GE(r.elapsedMs, 20.0);
}

TEST(SimEndToEnd, ModbusTcpGateway)
{
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                           QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")}));
    EXPECT_TRUE(sim.pty.isEmpty());
    const int colon = sim.tcp.lastIndexOf(QLatin1Char(':'));
    ASSERT_GT(colon, 0) << sim.tcp.toStdString();
    ConnectionSettings s;
    s.kind = ConnectionSettings::Kind::Tcp;
    s.host = sim.tcp.left(colon);
    s.tcpPort = sim.tcp.mid(colon + 1).toInt();
    s.retries = 0;
    ModbusClient client(std::make_unique<TcpBackend>(s), s);
    ASSERT_TRUE(client.openBlocking().isEmpty());
    const ModbusResult r = client.execute(ModbusRequest::readHolding(1, 0xCA03, 1));
    ASSERT_TRUE(r.ok()) << r.errorText().toStdString();
    EXPECT_EQ(r.registers.value(0), 1000);
}
