#include "sim/PtySimServer.h"

#include "transport/IoctlSerialDriver.h"

#include "sim/SimBus.h"
#include "sim/SimLog.h"
#include "transport/ModbusCrc.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QPointer>
#include <QSocketNotifier>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

namespace opentop {

namespace {

constexpr int kSilenceMs = 20; // framing of unknown functions and discarding partial frames

} // namespace

PtySimServer::PtySimServer(std::shared_ptr<SimBus> bus, const WireTiming& timing, bool wireTiming,
                           QObject* parent)
    : QObject(parent)
    , m_bus(std::move(bus))
    , m_timing(timing)
    , m_wireTiming(wireTiming)
    , m_replies(new ReplyScheduler([this](const QByteArray& reply) { send(reply); }, this))
{
    m_silence.setSingleShot(true);
    m_silence.setInterval(kSilenceMs);
    connect(&m_silence, &QTimer::timeout, this, &PtySimServer::onSilence);
}

PtySimServer::~PtySimServer()
{
    close();
}

bool PtySimServer::open(const QString& linkPath, QString* error)
{
    m_linkHolderPid = 0;
    // On replug the link is locked already.
    const bool lockNow = !linkPath.isEmpty() && !m_linkLock;
    if (lockNow && !lockLink(linkPath, error))
        return false;
    auto fail = [&](const QString& message) {
        if (error)
            *error = message;
        closePty();
        if (lockNow)
            m_linkLock.reset();
        return false;
    };
    char name[256] = {};
    if (::openpty(&m_master, &m_slave, name, nullptr, nullptr) != 0) {
        return fail(
            tr("cannot open a pseudo-terminal: %1").arg(QString::fromLocal8Bit(strerror(errno))));
    }
    m_slavePath = QString::fromLocal8Bit(name);
    termios tio = {};
    if (::tcgetattr(m_slave, &tio) == 0) {
        ::cfmakeraw(&tio);
        ::tcsetattr(m_slave, TCSANOW, &tio);
    }
    ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
    if (!linkPath.isEmpty()) {
        const QFileInfo info(linkPath);
        if (info.isSymLink()) {
            QFile::remove(linkPath); // left by a simulator that is gone: we hold its lock
        } else if (info.exists()) {
            return fail(tr("%1 exists and is not a symlink; refusing to replace it").arg(linkPath));
        }
        if (!QFile::link(m_slavePath, linkPath))
            return fail(tr("cannot create the symlink %1 -> %2").arg(linkPath, m_slavePath));
        m_linkPath = linkPath;
    }
    m_notifier = new QSocketNotifier(m_master, QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &PtySimServer::onReadable);
    qCInfo(lcSim) << "serving" << m_bus->spec() << "on" << m_slavePath;
    return true;
}

bool PtySimServer::lockLink(const QString& linkPath, QString* error)
{
    auto lock = std::make_unique<QLockFile>(linkPath + QStringLiteral(".lock"));
    // Held as long as the simulator runs, so never stale by age; stale only when the PID it
    // names no longer runs (a killed simulator), and then tryLock() removes it and takes over.
    lock->setStaleLockTime(0);
    int why = EEXIST;
    for (int attempt = 0; attempt < 2; ++attempt) {
        if (lock->tryLock(0)) {
            m_linkLock = std::move(lock);
            return true;
        }
        why = errno; // of the failed open() when the file cannot be created
        if (lock->error() != QLockFile::LockFailedError)
            break;
        why = EEXIST;
        qint64 pid = 0;
        if (lock->getLockInfo(&pid, nullptr, nullptr)) {
            m_linkHolderPid = pid;
            if (error)
                *error = tr("%1 is in use by another simulator (PID %2); stop it first, or "
                            "choose another path for --pty")
                             .arg(linkPath)
                             .arg(pid);
            return false;
        }
        // The holder let go between the two looks: try once more.
    }
    if (error)
        *error = tr("cannot create the lock file %1: %2")
                     .arg(lock->fileName(), QString::fromLocal8Bit(strerror(why)));
    return false;
}

void PtySimServer::close()
{
    closePty();
    m_linkLock.reset(); // unlocks: removes <link>.lock
}

void PtySimServer::closePty()
{
    delete m_notifier;
    m_notifier = nullptr;
    if (!m_linkPath.isEmpty()) {
        if (QFileInfo(m_linkPath).symLinkTarget() == m_slavePath)
            QFile::remove(m_linkPath);
        m_linkPath.clear();
    }
    if (m_master >= 0)
        ::close(m_master);
    if (m_slave >= 0)
        ::close(m_slave);
    m_master = m_slave = -1;
    m_replies->clear(); // a reply delayed past an unplug never reaches the next pty
}

void PtySimServer::unplug()
{
    m_unpluggedLink = m_linkPath;
    m_silence.stop();
    m_buffer.clear();
    closePty(); // the link stays locked: this simulator plugs it in again
    qCInfo(lcSim) << "unplugged";
}

bool PtySimServer::replug(QString* error)
{
    if (m_master >= 0) {
        if (error)
            *error = tr("the port is plugged in: %1").arg(m_slavePath);
        return false;
    }
    return open(m_unpluggedLink, error);
}

int PtySimServer::requestLength(const QByteArray& buffer)
{
    if (buffer.size() < 2)
        return 0;
    const quint8 function = quint8(buffer.at(1));
    if (function >= 0x01 && function <= 0x06)
        return 8;
    if (function == 0x0F || function == 0x10)
        return buffer.size() < 7 ? 0 : 9 + quint8(buffer.at(6));
    if (function == 0x2B)
        return 7;
    return -1;
}

void PtySimServer::onReadable()
{
    char chunk[512];
    // The format the client's port is in as the frame begins: TCGETS on a pty master returns
    // the slave's termios (hardware.md: a pty keeps rate, stop bits and INPCK/PARODD).
    if (m_buffer.isEmpty())
        m_frameLine = IoctlSerialDriver::formatOf(m_master);
    for (;;) {
        const ssize_t n = ::read(m_master, chunk, sizeof chunk);
        if (n > 0) {
            m_buffer.append(chunk, int(n));
            continue;
        }
        break; // EAGAIN (all read) or EIO (no client): wait for the next notification
    }
    processBuffer();
}

void PtySimServer::processBuffer()
{
    while (!m_buffer.isEmpty()) {
        const int length = requestLength(m_buffer);
        if (length <= 0 || m_buffer.size() < length)
            break; // more bytes, or a silence gap, will tell
        const QByteArray frame = m_buffer.left(length);
        m_buffer.remove(0, length);
        if (!ModbusCrc::check(frame)) {
            // Out of step (noise, a frame for an unknown length): resynchronise at silence.
            qCInfo(lcSim) << "rx" << frame.toHex(' ') << "bad CRC: ignored";
            m_buffer.clear();
            break;
        }
        dispatch(frame);
    }
    if (!m_buffer.isEmpty())
        m_silence.start();
}

void PtySimServer::onSilence()
{
    if (m_buffer.isEmpty())
        return;
    if (requestLength(m_buffer) < 0) {
        dispatch(m_buffer); // unknown function: the frame is everything before the gap
    } else {
        qCInfo(lcSim) << "rx" << m_buffer.toHex(' ') << "incomplete frame: ignored";
    }
    m_buffer.clear();
}

void PtySimServer::dispatch(const QByteArray& frame)
{
    const qint64 arrivedNs = ReplyScheduler::nowNs();
    if (m_wireTiming && m_halfDuplex && !lineAccepts(frame, arrivedNs))
        return;
    const WireTiming timing = frameTiming();
    const SimOutcome outcome = m_bus->handleFrame(frame, m_bus->nowMs(), m_frameLine);
    qCInfo(lcSim).noquote() << "rx" << frame.toHex(' ') << "tx"
                            << (outcome.reply.isEmpty()
                                    ? QStringLiteral("-")
                                    : QString::fromLatin1(outcome.reply.toHex(' ')));
    if (outcome.reply.isEmpty())
        return;
    double delay = outcome.delayMs;
    if (m_wireTiming)
        delay += timing.replyDelayMs(frame.size(), outcome.reply.size(), outcome.turnaroundMs);
    if (delay < 0.05) {
        send(outcome.reply);
        return;
    }
    ReplyScheduler::Reply reply;
    reply.bytes = outcome.reply;
    reply.dueNs = arrivedNs + qint64(delay * 1e6);
    reply.startNs = reply.dueNs - qint64(timing.frameMs(outcome.reply.size()) * 1e6);
    m_replies->schedule(reply);
}

WireTiming PtySimServer::frameTiming() const
{
    // On a bus with line settings (opentop-sim's --baud), the frame takes the time of the
    // format the client sent it in; a bare bus keeps the timing it was given.
    return m_bus->lineBaud() ? m_timing.at(m_frameLine) : m_timing;
}

bool PtySimServer::lineAccepts(const QByteArray& frame, qint64 nowNs)
{
    // The request is on the wire from now until its last character has gone.
    const qint64 endNs = nowNs + qint64(frameTiming().frameMs(frame.size()) * 1e6);
    bool collided = false;
    for (ReplyScheduler::Reply& r : m_replies->pending()) {
        if (nowNs < r.dueNs && endNs > r.startNs) {
            collided = true;
            r.bytes[r.bytes.size() - 1] = char(r.bytes.at(r.bytes.size() - 1) ^ 0xA5);
        }
    }
    if (collided) {
        ++m_collisions;
        qCInfo(lcSim) << "rx" << frame.toHex(' ') << "collided with a reply on the line: both lost";
        return false;
    }
    const double gapMs = double(nowNs - m_lastReplyEndNs) / 1e6;
    if (m_lastReplyEndNs > 0 && gapMs < frameTiming().gapMs()) {
        ++m_gapViolations;
        qCInfo(lcSim) << "rx" << frame.toHex(' ') << "only" << gapMs
                      << "ms after the last reply (less than 3.5 characters): not a frame";
        return false;
    }
    return true;
}

void PtySimServer::send(const QByteArray& reply)
{
    if (m_master < 0)
        return;
    m_lastReplyEndNs = ReplyScheduler::nowNs();
    int written = 0;
    while (written < reply.size()) {
        const ssize_t n =
            ::write(m_master, reply.constData() + written, size_t(reply.size() - written));
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN)
                continue;
            qCWarning(lcSim) << "pty write failed:" << strerror(errno);
            return;
        }
        written += int(n);
    }
}

} // namespace opentop
