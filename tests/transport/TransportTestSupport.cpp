#include "tests/transport/TransportTestSupport.h"

#include "transport/LateReplyJournal.h"
#include "transport/RtuFrame.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QThread>
#include <arpa/inet.h>
#include <cerrno>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <pty.h>
#include <stdexcept>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

namespace opentop::test {

namespace {

void writeAll(int fd, const QByteArray& bytes)
{
    qsizetype done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.constData() + done, size_t(bytes.size() - done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return;
        done += n;
    }
}

void sendAnswer(int fd, const Answer& answer, const std::atomic<bool>& stop)
{
    if (answer.delayMs > 0)
        QThread::msleep(ulong(answer.delayMs));
    if (stop)
        return;
    writeAll(fd, answer.bytes);
    if (answer.second.isEmpty())
        return;
    if (answer.secondDelayMs > 0)
        QThread::msleep(ulong(answer.secondDelayMs));
    writeAll(fd, answer.second);
}

} // namespace

QByteArray echoDevice(const QByteArray& adu)
{
    ModbusRequest r;
    if (!RtuFrame::decodeRequest(adu, &r))
        return QByteArray();
    switch (r.function) {
    case ModbusRequest::ReadHolding:
    case ModbusRequest::ReadInput: {
        QVector<quint16> values;
        for (int i = 0; i < r.count; ++i)
            values << quint16(r.address + i);
        return RtuFrame::encodeReadReply(r.slave, r.function, values);
    }
    case ModbusRequest::WriteSingle:
        return RtuFrame::encodeWriteSingleReply(r.slave, r.address, r.values.value(0));
    case ModbusRequest::WriteMultiple:
        return RtuFrame::encodeWriteMultipleReply(r.slave, r.address, r.count);
    default:
        return RtuFrame::encodeException(r.slave, r.function, 0x01);
    }
}

MockClient::MockClient(MockBackend::Handler handler, const ConnectionSettings& settings, bool open)
{
    auto backend = std::make_unique<MockBackend>(std::move(handler));
    mock = backend.get();
    client = std::make_unique<ModbusClient>(std::move(backend), settings);
    if (open) {
        EXPECT_EQ(client->openBlocking(), QString());
    }
}

bool waitUntil(const std::function<bool()>& done, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeoutMs)
            return done();
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        QThread::msleep(1);
    }
    return true;
}

int openDescriptorsOn(const QString& path)
{
    int count = 0;
    const QString target = QFileInfo(path).canonicalFilePath();
    const auto entries = QDir(QStringLiteral("/proc/self/fd")).entryInfoList(QDir::System);
    for (const QFileInfo& entry : entries)
        if (entry.symLinkTarget() == target)
            ++count;
    return count;
}

PtyDevice::PtyDevice()
{
    char name[256] = {};
    if (::openpty(&m_master, &m_slave, name, nullptr, nullptr) != 0)
        throw std::runtime_error("openpty failed");
    // Raw on both ends until libmodbus configures the line; the slave fd stays open so the
    // pty does not hang up between the client's open and close.
    for (int fd : {m_master, m_slave}) {
        termios tio{};
        ::tcgetattr(fd, &tio);
        ::cfmakeraw(&tio);
        ::tcsetattr(fd, TCSANOW, &tio);
    }
    m_path = QString::fromLocal8Bit(name);
    // A new device: what an earlier test left for a pty of the same number is not its own.
    LateReplyJournal(m_path).write({});
}

PtyDevice::~PtyDevice()
{
    stop();
    if (m_master >= 0)
        ::close(m_master);
    ::close(m_slave);
}

void PtyDevice::start(Script script)
{
    m_script = std::move(script);
    m_stop = false;
    m_thread = std::thread(&PtyDevice::run, this);
}

void PtyDevice::stop()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
}

void PtyDevice::closeMaster()
{
    stop();
    ::close(m_master);
    m_master = -1;
}

std::vector<QByteArray> PtyDevice::requests() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_requests;
}

void PtyDevice::run()
{
    QByteArray buffer;
    char chunk[512];
    while (!m_stop) {
        pollfd pfd{m_master, POLLIN, 0};
        if (::poll(&pfd, 1, 10) <= 0 || !(pfd.revents & POLLIN))
            continue;
        const ssize_t n = ::read(m_master, chunk, sizeof chunk);
        if (n <= 0) {
            QThread::msleep(5);
            continue;
        }
        buffer.append(chunk, int(n));
        for (;;) {
            int need = RtuFrame::expectedRequestLength(buffer);
            if (need == 0 || (need > 0 && buffer.size() < need))
                break;
            if (need < 0)
                need = int(buffer.size());
            const QByteArray frame = buffer.left(need);
            buffer.remove(0, need);
            {
                std::lock_guard<std::mutex> lock(m_mutex);
                m_requests.push_back(frame);
            }
            if (m_script)
                sendAnswer(m_master, m_script(frame), m_stop);
        }
    }
}

TcpDevice::TcpDevice()
{
    m_listen = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    int yes = 1;
    ::setsockopt(m_listen, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    if (::bind(m_listen, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
        ::listen(m_listen, 4) != 0)
        throw std::runtime_error("cannot listen on 127.0.0.1");
    socklen_t length = sizeof addr;
    ::getsockname(m_listen, reinterpret_cast<sockaddr*>(&addr), &length);
    m_port = ntohs(addr.sin_port);
}

TcpDevice::~TcpDevice()
{
    stop();
    if (m_connection >= 0)
        ::close(m_connection);
    ::close(m_listen);
}

void TcpDevice::start(Script script)
{
    m_script = std::move(script);
    m_stop = false;
    m_thread = std::thread(&TcpDevice::run, this);
}

void TcpDevice::stop()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
}

void TcpDevice::dropConnection()
{
    const int fd = m_connection;
    if (fd >= 0)
        ::shutdown(fd, SHUT_RDWR); // the server thread sees end of stream and closes it
}

std::vector<QByteArray> TcpDevice::requests() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_requests;
}

void TcpDevice::run()
{
    QByteArray buffer;
    char chunk[512];
    while (!m_stop) {
        const int connection = m_connection;
        pollfd pfd{connection >= 0 ? connection : m_listen, POLLIN, 0};
        if (::poll(&pfd, 1, 10) <= 0)
            continue;
        if (connection < 0) {
            m_connection = ::accept4(m_listen, nullptr, nullptr, SOCK_CLOEXEC);
            buffer.clear();
            continue;
        }
        const ssize_t n = ::recv(connection, chunk, sizeof chunk, 0);
        if (n <= 0) {
            ::close(connection);
            m_connection = -1;
            continue;
        }
        buffer.append(chunk, int(n));
        while (buffer.size() >= 7) {
            const int need = 6 + ((quint8(buffer[4]) << 8) | quint8(buffer[5]));
            if (buffer.size() < need)
                break;
            const QByteArray frame = buffer.left(need);
            buffer.remove(0, need);
            {
                std::lock_guard<std::mutex> lock(m_mutex);
                m_requests.push_back(frame);
            }
            if (m_script)
                sendAnswer(connection, m_script(frame), m_stop);
        }
    }
}

} // namespace opentop::test
