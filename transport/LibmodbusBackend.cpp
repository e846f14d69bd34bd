#include "transport/LibmodbusBackend.h"

#include "transport/RtuFrame.h"
#include "transport/TransportLog.h"

#include <QCoreApplication>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <modbus.h>
#include <poll.h>
#include <unistd.h>
#include <utility>

namespace opentop {

namespace {

constexpr int kBufferSize = MODBUS_TCP_MAX_ADU_LENGTH; // large enough for RTU too
constexpr double kSliceMs = 20; // waits are sliced so that an interrupt is seen quickly

QString errnoText(int err)
{
    return QString::fromLocal8Bit(modbus_strerror(err));
}

} // namespace

LibmodbusBackend::LibmodbusBackend(const ConnectionSettings& settings)
    : m_settings(settings)
    , m_line(settings)
{
    m_clock.start();
}

LibmodbusBackend::~LibmodbusBackend()
{
    // Subclasses call close() in their destructors; this only catches a missed one.
    if (m_ctx) {
        modbus_close(m_ctx);
        modbus_free(m_ctx);
    }
}

int LibmodbusBackend::turnaroundMs() const
{
    return m_turnaroundMs >= 0 ? m_turnaroundMs : defaultTurnaroundMs();
}

QString LibmodbusBackend::openErrorText(int err) const
{
    return QCoreApplication::translate("opentop::Transport", "Cannot open %1: %2")
        .arg(describe(), errnoText(err));
}

bool LibmodbusBackend::open(QString* error)
{
    LibmodbusBackend::close(); // not a subclass's: RtuBackend holds its port lock by now
    errno = 0;
    m_ctx = createContext();
    if (!m_ctx) {
        if (error)
            *error = openErrorText(errno ? errno : EINVAL);
        return false;
    }
    modbus_set_error_recovery(m_ctx, MODBUS_ERROR_RECOVERY_NONE);
    // For TCP this is the connect timeout: bounded so that closing never waits long.
    setResponseTimeout(std::clamp(m_settings.timeoutMs, 1000, 3000));
    const int byteTimeoutMs = m_settings.effectiveByteTimeoutMs();
    modbus_set_byte_timeout(m_ctx, uint32_t(byteTimeoutMs / 1000),
                            uint32_t((byteTimeoutMs % 1000) * 1000));
    if (modbus_connect(m_ctx) == -1) {
        const int err = errno;
        modbus_free(m_ctx);
        m_ctx = nullptr;
        if (error)
            *error = openErrorText(err);
        qCWarning(lcTransport) << "open failed:" << describe() << errnoText(err);
        return false;
    }
    modbus_flush(m_ctx);
    m_line = m_settings;
    m_open = true;
    // The program that used the line before us may have left a request unanswered (a CLI run
    // that gave up, then exited): its late reply can reach our first request of the same
    // shape. Until that window has passed, every reply is checked for another right behind it.
    m_suspectAllUntilMs =
        double(m_clock.nsecsElapsed()) / 1e6 + std::max(1000.0, 5.0 * m_settings.timeoutMs);
    qCDebug(lcTransport) << "opened" << describe();
    return true;
}

void LibmodbusBackend::close()
{
    if (!m_ctx)
        return;
    modbus_close(m_ctx);
    modbus_free(m_ctx);
    m_ctx = nullptr;
    m_open = false;
    m_lateWatch.clear();
    m_suspects.clear();
    m_checkedSinceOpen.clear();
    m_notes.clear();
    qCDebug(lcTransport) << "closed" << describe();
}

bool LibmodbusBackend::isOpen() const
{
    return m_open;
}

int LibmodbusBackend::descriptor() const
{
    return m_ctx ? modbus_get_socket(m_ctx) : -1;
}

void LibmodbusBackend::setResponseTimeout(double ms)
{
    // libmodbus rejects 0 s 0 µs.
    const auto us = static_cast<uint32_t>(std::max(1000.0, std::ceil(ms * 1000)));
    modbus_set_response_timeout(m_ctx, us / 1000000, us % 1000000);
}

ModbusResult LibmodbusBackend::transact(const ModbusRequest& request, int timeoutMs)
{
    ModbusResult result;
    if (!isOpen()) {
        result.error = ModbusError::NotConnected;
        result.message =
            QCoreApplication::translate("opentop::Transport", "%1 is not open").arg(describe());
        return result;
    }
    if (timeoutMs <= 0)
        timeoutMs = m_settings.timeoutMs;

    awaitLateReplies(request);
    // Held after a silent timeout (LineNotes): a reply meanwhile ends the wait once the line is
    // quiet for a gap and what the adapter may hold back; its sender is noted for the result.
    if (const double heldMs = m_notes.heldFor(request, nowMs()); heldMs > 0)
        drain(request, heldMs,
              std::max(1, int(std::ceil(std::max(frameGapMs(), wireTimeMs(4)) +
                                        lineReport().adapterLatencyMs()))));
    discardStaleInput(request);
    const LineFormat format = request.line.isSet() ? request.line : m_settings.line();
    if (format != m_line.line() && !switchLine(format, &result)) {
        logEvent(request, result.message, result.errorText());
        return result;
    }
    if (!keepFrameGap()) {
        result.error = ModbusError::Cancelled;
        return result;
    }
    // Also a reply swallowed by the previous request's recovery: whoever asked that drive
    // (a scan) hears of it with the next result.
    m_notes.passOn(&result);
    const QByteArray raw = char(request.slave) + request.pdu();
    const QByteArray sent = txAdu(request);
    // A frame in a drive's own format says so: the traffic log shows where the line switched.
    logFrame(true, sent, request,
             format == m_settings.line()
                 ? request.describe()
                 : QStringLiteral("%1 [%2]").arg(request.describe(), format.text()),
             QString());
    m_timer.start();
    m_sentAtMs = double(m_clock.nsecsElapsed()) / 1e6;
    if (modbus_send_raw_request(m_ctx, reinterpret_cast<const uint8_t*>(raw.constData()),
                                int(raw.size())) == -1) {
        portFailure(errno, QCoreApplication::translate("opentop::Transport", "send failed"),
                    &result);
        logEvent(request, QString(), result.errorText());
        return result;
    }

    if (request.isBroadcast()) {
        // No device answers a broadcast; they need the turnaround to execute it before the
        // next frame, counted from when the frame has left the UART.
        if (!sleepInterruptible(wireTimeMs(int(sent.size())) + turnaroundMs())) {
            result.error = ModbusError::Cancelled;
            return result;
        }
        result.error = ModbusError::Ok;
        result.elapsedMs = elapsedMs();
        return result;
    }

    // Until the request has left the UART the line is ours; a timeout is counted from there.
    m_lineActiveAtMs = m_sentAtMs + wireTimeMs(int(sent.size()));
    const int ready = waitReadable(timeoutMs);
    if (ready <= 0) {
        result.elapsedMs = elapsedMs();
        if (ready < 0) {
            result.error = ModbusError::Cancelled;
            result.message =
                QCoreApplication::translate("opentop::Transport", "interrupted while waiting");
            return result;
        }
        result.error = ModbusError::Timeout;
        result.message = QCoreApplication::translate("opentop::Transport", "no reply within %1 ms")
                             .arg(timeoutMs);
        logEvent(request, result.message, result.errorText());
        deferRecovery(request, timeoutMs);
        // Counted from sending, as the timeout is; TCP has no wire time and no gap.
        m_notes.hold(request, m_sentAtMs + timeoutMs +
                                  wireTimeMs(LineNotes::longestReplyBytes(request)) + frameGapMs());
        return result;
    }

    QByteArray adu;
    if (request.raw)
        readRawReply(request, timeoutMs, &adu, &result);
    else
        receiveStandard(request, timeoutMs, &adu, &result);
    result.reply = adu;
    result.elapsedMs = elapsedMs();
    m_lineActiveAtMs = nowMs();

    if (result.error == ModbusError::PortError || result.error == ModbusError::Cancelled) {
        logEvent(request, QString(), result.errorText());
        return result;
    }
    if (adu.isEmpty()) {
        logEvent(request, result.message, result.errorText());
    } else {
        const QByteArray rtu = toRtuAdu(adu);
        logReply(adu, quint8(rtu.at(0)), rtu.size() > 1 ? quint8(rtu.at(1)) : -1, request, result);
    }
    if ((result.error == ModbusError::Ok || result.error == ModbusError::Exception) &&
        isSuspect(request.slave) && anotherReplyFollows(request, int(sent.size() + adu.size()))) {
        result.error = ModbusError::MalformedReply;
        result.registers.clear();
        result.message = QCoreApplication::translate(
            "opentop::Transport",
            "another reply followed: this one may have answered an earlier request");
        logEvent(request, result.message, result.errorText());
    } else if (result.error == ModbusError::Ok || result.error == ModbusError::Exception) {
        m_checkedSinceOpen.insert(request.slave);
    }
    if (result.error != ModbusError::Ok && result.error != ModbusError::Exception) {
        recover(request, timeoutMs);
        m_notes.passOn(&result);
    }
    return result;
}

double LibmodbusBackend::nowMs() const
{
    return double(m_clock.nsecsElapsed()) / 1e6;
}

double LibmodbusBackend::frameGapMs() const
{
    return m_frameGapMs >= 0 ? m_frameGapMs : defaultFrameGapMs();
}

bool LibmodbusBackend::keepFrameGap()
{
    // Modbus RTU frames are told apart by 3.5 characters of silence, and a DBU does not
    // answer a request that follows the previous frame more closely. A fast adapter hands
    // over a reply so quickly that the next request could otherwise follow at once.
    const double waitMs = m_lineActiveAtMs + frameGapMs() - nowMs();
    return waitMs <= 0 || sleepInterruptible(waitMs);
}

bool LibmodbusBackend::applyLineFormat(const LineFormat&, QString* error)
{
    *error = QCoreApplication::translate("opentop::Transport",
                                         "a drive's own line format needs a serial port; a "
                                         "Modbus TCP gateway sets its line itself");
    return false;
}

bool LibmodbusBackend::switchLine(const LineFormat& format, ModbusResult* result)
{
    if (!keepFrameGap()) {
        result->error = ModbusError::Cancelled;
        return false;
    }
    QString error;
    if (!applyLineFormat(format, &error)) {
        result->error = ModbusError::PortError;
        result->message =
            QCoreApplication::translate("opentop::Transport", "cannot switch the line to %1: %2")
                .arg(format.text(), error);
        return false;
    }
    m_line.setLine(format);
    const int byteTimeoutMs = m_line.effectiveByteTimeoutMs();
    modbus_set_byte_timeout(m_ctx, uint32_t(byteTimeoutMs / 1000),
                            uint32_t((byteTimeoutMs % 1000) * 1000));
    return true;
}

void LibmodbusBackend::suspect(quint8 slave, int timeoutMs)
{
    // Long after the late-reply window: a master without transaction ids cannot wait that
    // long before every retry, but it can check the replies that follow.
    const double untilMs =
        double(m_clock.nsecsElapsed()) / 1e6 + std::max(3000.0, 10.0 * timeoutMs);
    for (LateWatch& w : m_suspects) {
        if (w.slave == slave) {
            w.untilMs = std::max(w.untilMs, untilMs);
            return;
        }
    }
    m_suspects.append({slave, untilMs, 0});
}

bool LibmodbusBackend::isSuspect(quint8 slave)
{
    if (wireTimeMs(1) <= 0)
        return false; // Modbus TCP: transaction ids tell replies apart
    const double nowMs = double(m_clock.nsecsElapsed()) / 1e6;
    // A slave answers its requests in order, so the previous program's unanswered request to
    // it is answered before ours: once one exchange with it has been checked, none of its
    // replies can still be on the way. Only the first exchange with each slave is checked.
    if (nowMs < m_suspectAllUntilMs && !m_checkedSinceOpen.contains(slave))
        return true;
    m_suspects.erase(std::remove_if(m_suspects.begin(), m_suspects.end(),
                                    [nowMs](const LateWatch& w) { return w.untilMs <= nowMs; }),
                     m_suspects.end());
    return std::any_of(m_suspects.begin(), m_suspects.end(),
                       [slave](const LateWatch& w) { return w.slave == slave; });
}

bool LibmodbusBackend::anotherReplyFollows(const ModbusRequest& request, int frameBytes)
{
    // The request's own reply, if the one taken was not it, ends at the latest a turnaround
    // and the frames' wire time after sending; a quiet time more covers the gap.
    const int quietMs = recoveryQuietMs(request);
    const double ownEndMs = wireTimeMs(frameBytes) + turnaroundMs() + quietMs;
    return waitReadable(std::max(double(quietMs), ownEndMs - elapsedMs())) == 1;
}

void LibmodbusBackend::receiveStandard(const ModbusRequest& request, int timeoutMs, QByteArray* adu,
                                       ModbusResult* result)
{
    QByteArray buffer(kBufferSize, '\0');
    modbus_set_slave(m_ctx, request.slave);
    setResponseTimeout(std::max(1.0, timeoutMs - elapsedMs()));
    errno = 0;
    const int rc = modbus_receive_confirmation(m_ctx, reinterpret_cast<uint8_t*>(buffer.data()));
    const int err = errno;
    if (rc > 0) {
        *adu = buffer.left(rc);
        RtuFrame::decodeReply(request, toRtuAdu(*adu), result);
        return;
    }
    if (rc == 0) {
        // libmodbus read a whole frame (by its function code) but it carries another id; it
        // did not check the CRC, so a garbled frame is told apart here.
        *adu = buffer.left(receivedLength(buffer));
        RtuFrame::decodeReply(request, toRtuAdu(*adu), result);
        if (result->error == ModbusError::Ok || result->error == ModbusError::Exception) {
            result->error = ModbusError::WrongSlave;
            result->message = QCoreApplication::translate("opentop::Transport",
                                                          "reply from slave %1, expected %2")
                                  .arg(quint8(adu->at(0)))
                                  .arg(request.slave);
        }
        return;
    }
    switch (err) {
    case ETIMEDOUT:
        // The reply started but stopped: a master discards such a frame.
        result->error = ModbusError::Timeout;
        result->message = QCoreApplication::translate("opentop::Transport", "reply incomplete");
        break;
    case EMBBADCRC:
        *adu = buffer.left(receivedLength(buffer));
        result->error = ModbusError::CrcError;
        result->message = QCoreApplication::translate("opentop::Transport", "CRC mismatch");
        break;
    case EMBBADDATA:
        result->error = ModbusError::MalformedReply;
        result->message = errnoText(err);
        break;
    default:
        portFailure(err, QCoreApplication::translate("opentop::Transport", "receive failed"),
                    result);
        break;
    }
}

int LibmodbusBackend::waitReadable(double timeoutMs) const
{
    const int fd = descriptor();
    if (fd < 0)
        return 0;
    QElapsedTimer timer;
    timer.start();
    for (;;) {
        if (interrupted())
            return -1;
        const double left = timeoutMs - double(timer.nsecsElapsed()) / 1e6;
        // ppoll: a wait of 1.2 ms must not become 2 ms (a whole millisecond per transaction is
        // 10 % of a fast line's time).
        const double slice = std::clamp(left, 0.0, kSliceMs);
        const auto ns = static_cast<long long>(slice * 1e6);
        const timespec ts{time_t(ns / 1000000000), long(ns % 1000000000)};
        pollfd pfd{fd, POLLIN, 0};
        const int rc = ::ppoll(&pfd, 1, &ts, nullptr);
        if (rc > 0)
            return 1; // data, hangup or error: the read that follows tells which
        if (rc < 0 && errno != EINTR)
            return 1;
        if (left <= kSliceMs)
            return 0;
    }
}

int LibmodbusBackend::readSome(char* buffer, int maximum) const
{
    const int fd = descriptor();
    if (fd < 0) {
        errno = EBADF;
        return -1;
    }
    for (;;) {
        const ssize_t n = ::read(fd, buffer, size_t(maximum));
        if (n < 0 && errno == EINTR)
            continue;
        return int(n);
    }
}

bool LibmodbusBackend::isFatalErrno(int err)
{
    switch (err) {
    case EIO:
    case ENXIO:
    case EBADF:
    case ENODEV:
    case ECONNRESET:
    case ECONNABORTED:
    case EPIPE:
    case ENOTCONN:
    case ESHUTDOWN:
        return true;
    default:
        return false;
    }
}

void LibmodbusBackend::portFailure(int err, const QString& what, ModbusResult* result)
{
    result->error = ModbusError::PortError;
    result->message = QStringLiteral("%1: %2").arg(what, errnoText(err));
    if (isFatalErrno(err)) {
        qCWarning(lcTransport) << describe() << "lost:" << result->message;
        close();
        result->message +=
            QCoreApplication::translate("opentop::Transport", " (connection closed)");
    }
}

void LibmodbusBackend::discardStaleInput(const ModbusRequest& request)
{
    // Bytes waiting before we send belong to no request of ours (a late reply, noise).
    QByteArray stale;
    char chunk[kBufferSize];
    while (stale.size() < 4096 && waitReadable(0) == 1) {
        const int n = readSome(chunk, kBufferSize);
        if (n <= 0)
            break; // the send that follows reports a failed port
        stale.append(chunk, n);
    }
    if (stale.isEmpty())
        return;
    m_lineActiveAtMs = nowMs();
    m_notes.noteDiscarded(toRtuAdu(stale));
    modbus_flush(m_ctx);
    logFrame(
        false, stale, request, QString(),
        QCoreApplication::translate("opentop::Transport", "stale bytes discarded before sending"));
}

int LibmodbusBackend::lateReplyWindowMs(const ModbusRequest& request, int timeoutMs) const
{
    return std::max(timeoutMs, recoveryQuietMs(request));
}

double LibmodbusBackend::replyDeadlineMs(const ModbusRequest& request, int timeoutMs) const
{
    return m_sentAtMs + timeoutMs + lateReplyWindowMs(request, timeoutMs);
}

void LibmodbusBackend::recover(const ModbusRequest& request, int timeoutMs)
{
    // What came may not have been the answer to this request (a late reply to an earlier one,
    // another device, noise), so the real answer may still be on its way: swallow whatever
    // arrives until the request's late-reply window is over, or until the line has been quiet
    // for a frame time after a frame, then flush. Neither the retry nor the next request may
    // read it.
    suspect(request.slave, timeoutMs);
    const int quietMs = recoveryQuietMs(request);
    const double nowMs = double(m_clock.nsecsElapsed()) / 1e6;
    drain(request, std::max(double(quietMs), replyDeadlineMs(request, timeoutMs) - nowMs), quietMs);
}

void LibmodbusBackend::deferRecovery(const ModbusRequest& request, int timeoutMs)
{
    suspect(request.slave, timeoutMs);
    m_lateWatch.append(
        {request.slave, replyDeadlineMs(request, timeoutMs), recoveryQuietMs(request)});
}

void LibmodbusBackend::awaitLateReplies(const ModbusRequest& request)
{
    const double nowMs = double(m_clock.nsecsElapsed()) / 1e6;
    m_lateWatch.erase(std::remove_if(m_lateWatch.begin(), m_lateWatch.end(),
                                     [nowMs](const LateWatch& w) { return w.untilMs <= nowMs; }),
                      m_lateWatch.end());
    if (m_lateWatch.isEmpty())
        return;
    // A late reply from the slave we are about to ask again would look like its answer, and a
    // broadcast gets no answer to check at all: wait out the quiet time. So do bytes already
    // arriving: a reply in progress would collide with our request on the line.
    const bool sameSlave =
        std::any_of(m_lateWatch.begin(), m_lateWatch.end(),
                    [&](const LateWatch& w) { return w.slave == request.slave; });
    if (!sameSlave && !request.isBroadcast() && waitReadable(0) != 1)
        return;
    double untilMs = nowMs;
    int quietMs = 0;
    for (const LateWatch& w : m_lateWatch) {
        untilMs = std::max(untilMs, w.untilMs);
        quietMs = std::max(quietMs, w.quietMs);
    }
    m_lateWatch.clear();
    drain(request, untilMs - nowMs, quietMs);
}

void LibmodbusBackend::drain(const ModbusRequest& request, double firstWindowMs, int quietMs)
{
    // A babbling line must not hold the bus for ever.
    const double limitMs = std::max(0.0, firstWindowMs) + 4.0 * quietMs + 100;
    QElapsedTimer timer;
    timer.start();
    QByteArray late;
    char chunk[kBufferSize];
    double window = std::max(0.0, firstWindowMs);
    while (double(timer.elapsed()) < limitMs && waitReadable(window) == 1) {
        const int n = readSome(chunk, kBufferSize);
        if (n <= 0)
            break;
        late.append(chunk, n);
        window = quietMs; // quiet again for a whole frame time after every byte
    }
    if (!m_ctx)
        return;
    modbus_flush(m_ctx);
    if (!late.isEmpty()) {
        m_lineActiveAtMs = nowMs();
        m_notes.noteDiscarded(toRtuAdu(late));
    }
    if (!late.isEmpty())
        logFrame(false, late, request, QString(),
                 QCoreApplication::translate("opentop::Transport",
                                             "late bytes discarded after an error"));
}

} // namespace opentop
