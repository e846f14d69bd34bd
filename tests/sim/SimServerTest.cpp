// The pty and TCP servers in process: framing by length and by silence, several frames in one
// write, symlinks, MBAP.
#include "tests/sim/SimTestSupport.h"

#include "sim/PtySimServer.h"
#include "sim/TcpSimServer.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

using namespace opentop;
using namespace opentop::test;

namespace {

class PtyServer : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        bus = SimBus::fromSpec(QStringLiteral("dbu200@1,dcpid@7"), &error);
        ASSERT_TRUE(bus);
    }
    void TearDown() override
    {
        if (fd >= 0)
            ::close(fd);
    }
    void start(bool wireTiming = false, const QString& link = QString())
    {
        server = std::make_unique<PtySimServer>(bus, WireTiming(19200, 'N', 2), wireTiming);
        QString error;
        ASSERT_TRUE(server->open(link, &error)) << error.toStdString();
        fd = ::open(server->slavePath().toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
        ASSERT_GE(fd, 0);
        termios tio = {};
        ::tcgetattr(fd, &tio);
        ::cfmakeraw(&tio);
        ::tcsetattr(fd, TCSANOW, &tio);
    }
    // Sends `request` and collects what comes back until `bytes` arrived or `timeoutMs` passed.
    QByteArray exchange(const QByteArray& request, int bytes, int timeoutMs = 500)
    {
        if (!request.isEmpty()) {
            EXPECT_EQ(::write(fd, request.constData(), size_t(request.size())), request.size());
        }
        QByteArray got;
        QElapsedTimer timer;
        timer.start();
        while (got.size() < bytes && timer.elapsed() < timeoutMs) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
            char chunk[256];
            const ssize_t n = ::read(fd, chunk, sizeof chunk);
            if (n > 0)
                got.append(chunk, int(n));
        }
        return got;
    }

    std::shared_ptr<SimBus> bus;
    std::unique_ptr<PtySimServer> server;
    int fd = -1;
};

} // namespace

TEST(PtySimServerFraming, RequestLengthPerFunction)
{
    EXPECT_EQ(PtySimServer::requestLength(hexBytes("01")), 0);
    EXPECT_EQ(PtySimServer::requestLength(hexBytes("01 03")), 8);
    EXPECT_EQ(PtySimServer::requestLength(hexBytes("01 06 00")), 8);
    EXPECT_EQ(PtySimServer::requestLength(hexBytes("01 10 04 03 00 02")), 0);
    EXPECT_EQ(PtySimServer::requestLength(hexBytes("01 10 04 03 00 02 04")), 13);
    EXPECT_EQ(PtySimServer::requestLength(hexBytes("07 2B 0E")), 7);
    EXPECT_EQ(PtySimServer::requestLength(hexBytes("01 41 00")), -1);
}

TEST_F(PtyServer, AnswersRequestsFramedByLength)
{
    start();
    EXPECT_EQ(exchange(hexBytes("01 03 CA 03 00 01 4B D2"), 7), hexBytes("01 03 02 03 E8 B8 FA"));
    // Two requests in one write: two replies, in order.
    const QByteArray two =
        hexBytes("01 03 CA 03 00 01 4B D2") + withCrc(hexBytes("07 03 00 10 00 01"));
    const QByteArray replies = exchange(two, 14);
    EXPECT_EQ(replies.left(7), hexBytes("01 03 02 03 E8 B8 FA"));
    EXPECT_EQ(replies.mid(7), withCrc(hexBytes("07 03 02 00 00")));
    // A frame split over two writes.
    const QByteArray frame = hexBytes("01 10 04 03 00 02 04 00 00 00 64 80 91");
    exchange(frame.left(5), 0, 5);
    EXPECT_EQ(exchange(frame.mid(5), 8), hexBytes("01 10 04 03 00 02 B0 F8"));
}

TEST_F(PtyServer, UnknownFunctionFramedBySilence)
{
    start();
    EXPECT_EQ(exchange(withCrc(hexBytes("01 41 00 00")), 5), withCrc(hexBytes("01 C1 01")));
}

TEST_F(PtyServer, BadCrcIsIgnoredAndTheNextFrameAnswered)
{
    start();
    EXPECT_TRUE(exchange(hexBytes("01 03 CA 03 00 01 4B D3"), 1, 100).isEmpty());
    EXPECT_EQ(exchange(hexBytes("01 03 CA 03 00 01 4B D2"), 7), hexBytes("01 03 02 03 E8 B8 FA"));
    EXPECT_TRUE(exchange(withCrc(hexBytes("09 03 00 10 00 01")), 1, 100).isEmpty()); // unknown id
}

TEST_F(PtyServer, WireTimingDelaysTheReply)
{
    start(true);
    QElapsedTimer timer;
    timer.start();
    EXPECT_EQ(exchange(hexBytes("01 03 CA 03 00 01 4B D2"), 7).size(), 7);
    EXPECT_GE(timer.elapsed(), 11); // 8 + 7 characters, gap and 2 ms turnaround at 19200
}

TEST_F(PtyServer, SymlinkCreatedAndRemoved)
{
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("ttySIM"));
    start(false, link);
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), server->slavePath());
    server->close();
    EXPECT_FALSE(QFileInfo::exists(link));
    EXPECT_FALSE(QFileInfo(link).isSymLink());

    QFile regular(dir.filePath(QStringLiteral("file")));
    ASSERT_TRUE(regular.open(QIODevice::WriteOnly));
    regular.close();
    PtySimServer other(bus, WireTiming(), false);
    QString error;
    EXPECT_FALSE(other.open(regular.fileName(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("not a symlink"))) << error.toStdString();
}

TEST(TcpSimServerTest, ServesMbapToSeveralClients)
{
    QString error;
    auto bus = SimBus::fromSpec(QStringLiteral("dbu200@1"), &error);
    TcpSimServer server(bus, WireTiming(), false);
    ASSERT_TRUE(server.listen(QHostAddress::LocalHost, 0, &error)) << error.toStdString();
    QTcpSocket a;
    QTcpSocket b;
    a.connectToHost(QHostAddress::LocalHost, server.port());
    b.connectToHost(QHostAddress::LocalHost, server.port());
    ASSERT_TRUE(a.waitForConnected(1000));
    ASSERT_TRUE(b.waitForConnected(1000));
    a.write(hexBytes("00 05 00 00 00 06 01 03 CA 03 00 01"));
    b.write(hexBytes("00 09 00 00 00 06 01 06 CA 03 05 DC"));
    QElapsedTimer timer;
    timer.start();
    while ((a.bytesAvailable() < 11 || b.bytesAvailable() < 12) && timer.elapsed() < 2000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    EXPECT_EQ(a.readAll(), hexBytes("00 05 00 00 00 05 01 03 02 03 E8"));
    EXPECT_EQ(b.readAll(), hexBytes("00 09 00 00 00 06 01 06 CA 03 05 DC"));
    EXPECT_EQ(bus->device(1)->raw(QStringLiteral("spno2.speed")), 1500);
}
