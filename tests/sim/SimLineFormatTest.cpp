// Each simulated drive has line settings of its own: a frame sent in another format is noise to
// it (no answer), so a DC controller at 8E1 on a DBU bus at 8N1 shows as it does on a wire. On
// a pty the simulator reads the client's format from the master (TCGETS).
#include "tests/sim/SimTestSupport.h"

#include "sim/PtySimServer.h"
#include "sim/SimBackend.h"
#include "transport/ModbusClient.h"
#include "transport/ModbusRequest.h"
#include "transport/RtuBackend.h"
#include "transport/RtuFrame.h"

#include <QCoreApplication>
#include <QElapsedTimer>

using namespace opentop;
using namespace opentop::test;

namespace {

const LineFormat k8N1{19200, 'N', 8, 1};
const LineFormat k8E1{19200, 'E', 8, 1};

bool answers(SimBus& bus, int slave, const LineFormat& line)
{
    const QByteArray adu =
        RtuFrame::encodeRequest(ModbusRequest::readHolding(quint8(slave), 0x0000, 1));
    return !bus.handleFrame(adu, bus.nowMs(), line).reply.isEmpty();
}

std::shared_ptr<SimBus> mixedBus(const char* spec = "dbu200@1,dcpid@7{format=8E1,baud=19200}")
{
    QString error;
    auto bus = SimBus::fromSpec(QString::fromLatin1(spec), &error);
    EXPECT_TRUE(bus) << error.toStdString();
    if (bus)
        bus->setLine(19200, 'N'); // opentop-sim's --baud and --parity
    return bus;
}

ModbusResult run(ModbusClient& client, const ModbusRequest& request)
{
    bool done = false;
    ModbusResult result;
    client.submit(request, nullptr, [&](const ModbusResult& r) {
        result = r;
        done = true;
    });
    QElapsedTimer timer;
    timer.start();
    while (!done && timer.elapsed() < 3000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    EXPECT_TRUE(done);
    return result;
}

} // namespace

TEST(SimLineFormat, ADeviceAt8E1IgnoresFramesAt8N1AndAnswersFramesAt8E1)
{
    auto bus = mixedBus();
    ASSERT_TRUE(bus);
    EXPECT_FALSE(answers(*bus, 7, k8N1));
    EXPECT_TRUE(answers(*bus, 7, k8E1));
    EXPECT_TRUE(answers(*bus, 1, k8N1));
    EXPECT_FALSE(answers(*bus, 1, k8E1)); // a DBU works only at 8N1
    EXPECT_FALSE(answers(*bus, 7, {9600, 'E', 8, 1}));
    // setLine configured the DBU to the line, not the drive with settings of its own.
    EXPECT_EQ(bus->device(7)->lineFormat(), k8E1);
    EXPECT_TRUE(bus->hasOwnLine(7));
    EXPECT_FALSE(bus->hasOwnLine(1));
    EXPECT_EQ(bus->spec(), QStringLiteral("dbu200@1,dcpid@7{format=8E1,baud=19200}"));
}

TEST(SimLineFormat, AnOwnFormatDefaultsToTheProfilesAndKeepsTheDefects)
{
    auto bus = mixedBus("dbu200@1,dcpid@7{format=8N2,stall}");
    ASSERT_TRUE(bus);
    // Baud left out: the profile's (9600). 8N2 is heard at 8N1: a receiver checks one stop bit.
    EXPECT_EQ(bus->device(7)->lineFormat(), (LineFormat{9600, 'N', 8, 2}));
    EXPECT_TRUE(answers(*bus, 7, {9600, 'N', 8, 1}));
    EXPECT_FALSE(answers(*bus, 7, k8N1));
    EXPECT_TRUE(bus->device(7)->defects().stall);
}

TEST(SimLineFormat, AFormatTheDriveDoesNotOfferIsRefusedNamingWhatItOffers)
{
    QString error;
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dbu200@1{format=8E1}"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("8N1"))) << error.toStdString();
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dcpid@7{format=8N1}"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("8E1, 8O1, 8N2"))) << error.toStdString();
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dcpid@7{baud=14400}"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("9600"))) << error.toStdString();
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dcpid@7{format=9E1}"), &error));
}

TEST(SimLineFormat, InProcessTheMastersFormatIsKnownDirectly)
{
    auto bus = mixedBus();
    ASSERT_TRUE(bus);
    SimBackend backend(bus);
    backend.setPortLine(k8N1);
    QString error;
    ASSERT_TRUE(backend.open(&error));
    ModbusRequest request = ModbusRequest::readHolding(7, 0x0000, 1);
    EXPECT_EQ(backend.transact(request, 50).error, ModbusError::Timeout);
    request.line = k8E1;
    EXPECT_TRUE(backend.transact(request, 50).ok());
    EXPECT_TRUE(backend.transact(ModbusRequest::readInput(1, 0x0007, 5), 50).ok());
}

TEST(SimLineFormat, OnAPtyTheSimulatorReadsTheClientsFormat)
{
    auto bus = mixedBus();
    ASSERT_TRUE(bus);
    PtySimServer server(bus, WireTiming(19200, 'N', 2), false);
    QString error;
    ASSERT_TRUE(server.open(QString(), &error)) << error.toStdString();
    ConnectionSettings settings;
    settings.port = server.slavePath();
    settings.baud = 19200;
    settings.timeoutMs = 100;
    settings.retries = 0;
    ModbusClient client(std::make_unique<RtuBackend>(settings), settings);
    ASSERT_TRUE(client.openBlocking().isEmpty());
    EXPECT_EQ(run(client, ModbusRequest::readHolding(7, 0x0000, 1)).error, ModbusError::Timeout);
    client.setDriveLine(7, k8E1);
    EXPECT_TRUE(run(client, ModbusRequest::readHolding(7, 0x0000, 1)).ok());
    EXPECT_TRUE(run(client, ModbusRequest::readInput(1, 0x0007, 5)).ok());
    // A broadcast goes out in both formats: each drive executes it.
    ASSERT_TRUE(run(client, ModbusRequest::writeSingle(0, 0x0081, 7)).ok()); // DC stall time
    // The simulator's thread takes the frame off the pty when it runs: nothing answers a
    // broadcast, so the client is done first on a loaded machine.
    QElapsedTimer clock;
    clock.start();
    while (bus->device(7)->raw(QStringLiteral("config.stall_time")).value_or(-1) != 7 &&
           clock.elapsed() < 2000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    EXPECT_EQ(bus->device(7)->raw(QStringLiteral("config.stall_time")).value_or(-1), 7);
}

TEST(SimLineFormat, ADcControllerJoinsTheDbuBusAsTheProfileSays)
{
    // Factory format 9600 8E1 on a DBU bus at 19200 8N1.
    auto bus = mixedBus("dbu200@1,dcpid@7{format=8E1}");
    ASSERT_TRUE(bus);
    const LineFormat own{9600, 'E', 8, 1};
    SimDevice* dc = bus->device(7);
    // Step 2: parity "None, 2 stop bits" and 19200 bit/s as the one-frame configuration write
    // (0x10, the 15 registers from 0x0080), the others kept.
    QVector<quint16> block;
    for (quint16 a = 0x0080; a < 0x0080 + 15; ++a)
        block << dc->reg(3, a);
    block[0x8A - 0x80] = 0;
    block[0x8B - 0x80] = 19200;
    block[0x8C - 0x80] = 0;
    const QByteArray write =
        RtuFrame::encodeRequest(ModbusRequest::writeMultiple(7, 0x0080, block));
    EXPECT_TRUE(bus->handleFrame(write, bus->nowMs(), k8N1).reply.isEmpty()); // not heard
    ASSERT_FALSE(bus->handleFrame(write, bus->nowMs(), own).reply.isEmpty());
    // Step 3: still the old format until the next power-up.
    EXPECT_TRUE(answers(*bus, 7, own));
    EXPECT_FALSE(answers(*bus, 7, k8N1));
    dc->powerCycle(bus->nowMs());
    // Step 4: it answers with the DBUs at 19200 8N1 (its 8N2 is heard there), no longer at 8E1.
    EXPECT_EQ(dc->lineFormat(), (LineFormat{19200, 'N', 8, 2}));
    EXPECT_TRUE(answers(*bus, 7, k8N1));
    EXPECT_FALSE(answers(*bus, 7, own));
}
