// TcpBackend against a tiny Modbus TCP server on 127.0.0.1 run by the test.
#include "transport/TcpBackend.h"
#include "tests/transport/TransportTestSupport.h"
#include "transport/DeviceIdentification.h"
#include "transport/ModbusCrc.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficLog.h"

#include <QElapsedTimer>
#include <QThread>
#include <gtest/gtest.h>

using namespace opentop;
using namespace opentop::test;

namespace {

// An RTU reply turned into a TCP ADU answering `request` (same transaction id).
QByteArray tcpReply(const QByteArray& request, const QByteArray& rtuReply)
{
    const QByteArray pdu = rtuReply.mid(1, rtuReply.size() - 3);
    QByteArray adu = request.left(4);
    const int length = int(pdu.size()) + 1;
    adu.append(char(length >> 8));
    adu.append(char(length & 0xFF));
    adu.append(rtuReply.at(0));
    adu.append(pdu);
    return adu;
}

// The RTU view of a TCP request, to reuse RtuFrame::decodeRequest.
ModbusRequest decodeTcp(const QByteArray& adu)
{
    ModbusRequest r;
    RtuFrame::decodeRequest(ModbusCrc::append(adu.mid(6)), &r);
    return r;
}

struct TcpFixture
{
    TcpDevice server;
    TrafficLog log;
    std::unique_ptr<TcpBackend> backend;

    explicit TcpFixture(Script script)
    {
        server.start(std::move(script));
        ConnectionSettings s;
        s.kind = ConnectionSettings::Kind::Tcp;
        s.host = QStringLiteral("127.0.0.1");
        s.tcpPort = server.port();
        s.timeoutMs = 200;
        backend = std::make_unique<TcpBackend>(s);
        backend->setTrafficLog(&log);
        QString error;
        EXPECT_TRUE(backend->open(&error)) << error.toStdString();
    }
    ~TcpFixture() { backend.reset(); }
};

Answer answer(const QByteArray& bytes)
{
    Answer a;
    a.bytes = bytes;
    return a;
}

// Unit 5 is a drive behind the gateway; unit 6 is unreachable (gateway exception 0x0B);
// unit 7 answers with the wrong unit id; unit 8 is silent.
Answer gateway(const QByteArray& request)
{
    const ModbusRequest r = decodeTcp(request);
    switch (r.slave) {
    case 5:
        if (r.function == ModbusRequest::EncapsulatedInterface) {
            DeviceIdentification id;
            id.objects[0] = "Gateway";
            id.objects[1] = "DBU200-D";
            return answer(tcpReply(request, RtuFrame::encodeRaw(5, 0x2B, id.encode())));
        }
        if (r.function == ModbusRequest::WriteSingle)
            return answer(
                tcpReply(request, RtuFrame::encodeWriteSingleReply(5, r.address, r.values[0])));
        return answer(
            tcpReply(request, RtuFrame::encodeReadReply(5, r.function, {quint16(r.address + 1)})));
    case 6:
        return answer(tcpReply(request, RtuFrame::encodeException(6, r.function, 0x0B)));
    case 7:
        return answer(tcpReply(request, RtuFrame::encodeReadReply(9, r.function, {1})));
    default:
        return Answer();
    }
}

} // namespace

TEST(TcpBackendTest, ReadAndWriteThroughGateway)
{
    TcpFixture f(gateway);
    ModbusResult r = f.backend->transact(ModbusRequest::readInput(5, 0x0109, 1), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.registers, QVector<quint16>({0x010A}));
    r = f.backend->transact(ModbusRequest::writeSingle(5, 3, 1500), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    ASSERT_EQ(f.server.requests().size(), 2u);
    // MBAP: transaction 0, protocol 0, length 6, unit 5, then the PDU.
    EXPECT_EQ(f.server.requests()[0],
              RtuFrame::fromHex(QStringLiteral("00 00 00 00 00 06 05 04 01 09 00 01")));
    const auto entries = f.log.entries();
    ASSERT_EQ(entries.size(), 4);
    EXPECT_EQ(entries[0].bytes, f.server.requests()[0]);
    EXPECT_EQ(entries[1].summary, QStringLiteral("→ 266"));
}

TEST(TcpBackendTest, GatewayExceptionsAndWrongUnit)
{
    TcpFixture f(gateway);
    ModbusResult r = f.backend->transact(ModbusRequest::readHolding(6, 0, 1), 200);
    EXPECT_EQ(r.error, ModbusError::Exception);
    EXPECT_EQ(r.exceptionCode, 0x0B);
    EXPECT_EQ(r.errorText(),
              QStringLiteral("exception 0B Gateway target device failed to respond"));
    EXPECT_EQ(f.backend->transact(ModbusRequest::readHolding(7, 0, 1), 200).error,
              ModbusError::WrongSlave);
    EXPECT_EQ(f.backend->transact(ModbusRequest::readHolding(5, 1, 1), 200).registers,
              QVector<quint16>({2}));
}

TEST(TcpBackendTest, DeviceIdentificationByMbapLength)
{
    TcpFixture f(gateway);
    const ModbusResult r = f.backend->transact(ModbusRequest::readDeviceIdentification(5), 200);
    ASSERT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    DeviceIdentification id;
    ASSERT_TRUE(DeviceIdentification::parse(r.rawData, &id));
    EXPECT_EQ(id.text(1), QStringLiteral("DBU200-D"));
    const ModbusResult ex = f.backend->transact(ModbusRequest::readDeviceIdentification(6), 200);
    EXPECT_EQ(ex.error, ModbusError::Exception);
    EXPECT_EQ(ex.exceptionCode, 0x0B);
}

TEST(TcpBackendTest, TimeoutThenServerGoneIsPortError)
{
    TcpFixture f(gateway);
    QElapsedTimer timer;
    timer.start();
    EXPECT_EQ(f.backend->transact(ModbusRequest::readHolding(8, 0, 1), 100).error,
              ModbusError::Timeout);
    EXPECT_GE(timer.elapsed(), 95);
    EXPECT_EQ(f.backend->transact(ModbusRequest::readHolding(5, 0, 1), 200).error, ModbusError::Ok);
    f.server.dropConnection();
    QThread::msleep(50); // the server thread notices and closes its end
    const ModbusResult r = f.backend->transact(ModbusRequest::readHolding(5, 0, 1), 200);
    EXPECT_EQ(r.error, ModbusError::PortError) << r.errorText().toStdString();
    EXPECT_FALSE(f.backend->isOpen());
}

TEST(TcpBackendTest, ConnectRefused)
{
    int port = 0;
    {
        TcpDevice probe; // take a free port, then close it again
        port = probe.port();
    }
    ConnectionSettings s;
    s.kind = ConnectionSettings::Kind::Tcp;
    s.tcpPort = port;
    TcpBackend backend(s);
    QString error;
    EXPECT_FALSE(backend.open(&error));
    EXPECT_TRUE(error.contains(QString::number(port))) << error.toStdString();
    EXPECT_FALSE(error.contains(QStringLiteral("was not found"))) << error.toStdString();
}

// A gateway name that does not resolve is said as such (libmodbus says "Connection refused",
// which sends people to the port); a refused connection to an address stays "refused".
TEST(TcpBackendTest, ANameThatDoesNotResolveIsSaidAsSuch)
{
    ConnectionSettings s;
    s.kind = ConnectionSettings::Kind::Tcp;
    s.host = QStringLiteral("no-such-gateway.invalid"); // RFC 2606: never resolves
    s.tcpPort = 502;
    TcpBackend backend(s);
    QString error;
    EXPECT_FALSE(backend.open(&error));
    EXPECT_TRUE(error.contains(QStringLiteral("the name no-such-gateway.invalid was not found")))
        << error.toStdString();
    EXPECT_FALSE(error.contains(QStringLiteral("refused"))) << error.toStdString();
}
