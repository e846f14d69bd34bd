// The pty pulled out and plugged in again (console unplug / replug): the client's port fails,
// the symlink goes, a new pty appears behind the same symlink and the devices keep their state.
#include "tests/sim/SimTestSupport.h"

#include "sim/PtySimServer.h"
#include "sim/SimConsole.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>
#include <cerrno>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

using namespace opentop;
using namespace opentop::test;

namespace {

int openRaw(const QString& path)
{
    const int fd = ::open(path.toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd >= 0) {
        termios tio = {};
        ::tcgetattr(fd, &tio);
        ::cfmakeraw(&tio);
        ::tcsetattr(fd, TCSANOW, &tio);
    }
    return fd;
}

// Writes `request` and collects the reply until `bytes` arrived or half a second passed.
QByteArray exchange(int fd, const QByteArray& request, int bytes)
{
    EXPECT_EQ(::write(fd, request.constData(), size_t(request.size())), request.size());
    QByteArray got;
    QElapsedTimer timer;
    timer.start();
    while (got.size() < bytes && timer.elapsed() < 500) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        char chunk[256];
        const ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n > 0)
            got.append(chunk, int(n));
    }
    return got;
}

} // namespace

TEST(PtyReplug, UnplugFailsTheClientAndReplugServesTheSameDevicesAtTheSameLink)
{
    QString error;
    std::shared_ptr<SimBus> bus = SimBus::fromSpec(QStringLiteral("dbu200@1"), &error);
    ASSERT_TRUE(bus);
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("ttySIM"));
    PtySimServer server(bus, WireTiming(19200, 'N', 2), false);
    ASSERT_TRUE(server.open(link, &error)) << error.toStdString();
    ASSERT_TRUE(
        bus->control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("1234")})
            .ok);

    int fd = openRaw(link);
    ASSERT_GE(fd, 0);
    const QByteArray read = withCrc(hexBytes("01 03 CA 03 00 01"));
    EXPECT_EQ(exchange(fd, read, 7), withCrc(hexBytes("01 03 02 04 D2")));

    server.unplug();
    EXPECT_FALSE(server.isOpen());
    EXPECT_FALSE(QFileInfo(link).isSymLink());
    // The client's port failed, as a pulled USB adapter's does: reads hang up, writes fail.
    char byte = 0;
    EXPECT_LE(::read(fd, &byte, 1), 0);
    errno = 0;
    EXPECT_LT(::write(fd, read.constData(), size_t(read.size())), 0);
    EXPECT_EQ(errno, EIO);
    ::close(fd);
    ASSERT_TRUE(server.replug(&error)) << error.toStdString();
    EXPECT_FALSE(server.replug(&error)); // plugged in already

    EXPECT_TRUE(server.isOpen());
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), server.slavePath());
    fd = openRaw(link);
    ASSERT_GE(fd, 0);
    EXPECT_EQ(exchange(fd, read, 7), withCrc(hexBytes("01 03 02 04 D2"))); // state kept
    ::close(fd);
}

TEST(PtyReplug, ConsoleCommandsUseTheHooksOrRefuse)
{
    QString error;
    std::shared_ptr<SimBus> bus = SimBus::fromSpec(QStringLiteral("dbu200@1"), &error);
    ASSERT_TRUE(bus);
    SimConsole console(bus);
    EXPECT_FALSE(console.execute(QStringLiteral("unplug")).ok); // no pty server
    EXPECT_FALSE(console.execute(QStringLiteral("replug")).ok);
    int unplugs = 0;
    int replugs = 0;
    console.setPortHooks(
        [&unplugs] {
            ++unplugs;
            return SimControlResult{true, QStringLiteral("unplugged")};
        },
        [&replugs] {
            ++replugs;
            return SimControlResult{true, QStringLiteral("pty: /dev/pts/9")};
        });
    EXPECT_EQ(console.execute(QStringLiteral("unplug")).text, QStringLiteral("unplugged"));
    EXPECT_EQ(console.execute(QStringLiteral(" REPLUG ")).text, QStringLiteral("pty: /dev/pts/9"));
    EXPECT_EQ(unplugs, 1);
    EXPECT_EQ(replugs, 1);
    EXPECT_TRUE(SimConsole::helpText().contains(QStringLiteral("unplug")));
}
