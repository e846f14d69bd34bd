#include "transport/LibmodbusBackend.h"

#include "transport/RtuFrame.h"
#include "transport/TransportLog.h"

#include <QCoreApplication>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <modbus.h>
#include <utility>

namespace opentop {

LibmodbusBackend::LibmodbusBackend(const ConnectionSettings& settings)
    : m_settings(settings)
    , m_line(settings)
{
}

// Subclasses call close() in their destructors; m_modbus frees a context they missed.
LibmodbusBackend::~LibmodbusBackend() = default;

QString LibmodbusBackend::openErrorText(int err) const
{
    return QCoreApplication::translate("opentop::Transport", "Cannot open %1: %2")
        .arg(describe(), LibmodbusContext::errorText(err));
}

bool LibmodbusBackend::open(QString* error)
{
    LibmodbusBackend::close(); // not a subclass's: RtuBackend holds its port lock by now
    errno = 0;
    _modbus* ctx = createContext();
    if (!ctx) {
        if (error)
            *error = openErrorText(errno ? errno : EINVAL);
        return false;
    }
    // For TCP the response timeout is the connect timeout: bounded so that closing never waits
    // long.
    if (const int err = m_modbus.connect(ctx, std::clamp(m_settings.timeoutMs, 1000, 3000),
                                         m_settings.effectiveByteTimeoutMs())) {
        if (error)
            *error = openErrorText(err);
        qCWarning(lcTransport) << "open failed:" << describe() << LibmodbusContext::errorText(err);
        return false;
    }
    m_line = m_settings;
    m_open = true;
    // A request the line's previous user left unanswered may still be answered (LateReplyWatch).
    m_late.opened(nowMs(), m_settings.timeoutMs);
    qCDebug(lcTransport) << "opened" << describe();
    return true;
}

void LibmodbusBackend::close()
{
    if (!m_modbus.get())
        return;
    m_modbus.reset();
    m_open = false;
    m_late.clear();
    m_notes.clear();
    m_replyTiming.reset();
    qCDebug(lcTransport) << "closed" << describe();
}

bool LibmodbusBackend::isOpen() const
{
    return m_open;
}

ModbusResult LibmodbusBackend::transact(const ModbusRequest& request, int timeoutMs)
{
    ModbusResult result = exchange(request, timeoutMs);
    // A read answered while a read of the same length to the same drive is still unanswered:
    // the reply may be that one's late answer, which no timing can tell apart (a drive that
    // answers both late). Read again until two replies agree.
    if (wireTimeMs(1) <= 0 || !request.isRead() || request.raw)
        return result;
    for (int again = 0;
         result.error == ModbusError::Ok && again < 3 && m_late.ambiguous(request, nowMs());
         ++again) {
        ModbusResult second = exchange(request, timeoutMs);
        if (second.error != ModbusError::Ok || second.registers == result.registers) {
            if (second.error == ModbusError::Ok)
                logEvent(request,
                         QCoreApplication::translate(
                             "opentop::Transport",
                             "read twice: a read of the same length was unanswered, and the "
                             "first reply could have been its late answer"),
                         QString());
            return second;
        }
        m_late.unanswered(request, nowMs(), m_settings.timeoutMs);
        result = second;
    }
    if (result.error == ModbusError::Ok && m_late.ambiguous(request, nowMs())) {
        result.error = ModbusError::MalformedReply;
        result.registers.clear();
        result.message = QCoreApplication::translate(
            "opentop::Transport", "replies disagree: late answers to earlier reads are likely");
        logEvent(request, result.message, result.errorText());
    }
    return result;
}

ModbusResult LibmodbusBackend::exchange(const ModbusRequest& request, int timeoutMs)
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
    // The line must be quiet for the gap before we send: bytes that arrive meanwhile are a
    // reply nobody is waiting for, and would run into the request or be taken for its answer.
    for (int round = 0;; ++round) {
        if (!keepFrameGap()) {
            result.error = ModbusError::Cancelled;
            return result;
        }
        if (round == 4 || wireTimeMs(1) <= 0 || waitReadable(0) != 1)
            break;
        discardStaleInput(request);
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
    m_sentBytes = int(sent.size());
    m_earlyReplies = 0;
    m_timing.sending();
    if (!m_modbus.sendRaw(raw)) {
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
    m_timing.activeUntil(m_timing.sentAtMs() + wireTimeMs(int(sent.size())));
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
        // The wait for a late reply is deferred to the next request that needs it.
        m_late.timedOut(request.slave, nowMs(), timeoutMs, replyDeadlineMs(request, timeoutMs),
                        recoveryQuietMs(request));
        m_late.unanswered(request, nowMs(), timeoutMs);
        // Counted from sending, as the timeout is; TCP has no wire time and no gap.
        m_notes.hold(request, m_timing.sentAtMs() + timeoutMs +
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
    m_timing.activeUntil(nowMs());

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
        anotherReplyFollows(request, int(sent.size() + adu.size()))) {
        result.error = ModbusError::MalformedReply;
        result.registers.clear();
        result.message = QCoreApplication::translate(
            "opentop::Transport",
            "another reply followed: this one may have answered an earlier request");
        logEvent(request, result.message, result.errorText());
    } else if (result.error == ModbusError::Ok || result.error == ModbusError::Exception) {
        m_late.checked(request.slave);
        if (!m_earlyReplies)
            m_replyTiming.learn(result.elapsedMs, wireTimeMs(int(sent.size() + adu.size())));
    }
    if (result.error != ModbusError::Ok && result.error != ModbusError::Exception) {
        recover(request, timeoutMs);
        m_notes.passOn(&result);
    }
    return result;
}

bool LibmodbusBackend::keepFrameGap()
{
    // Modbus RTU frames are told apart by 3.5 characters of silence, and a DBU does not
    // answer a request that follows the previous frame more closely. A fast adapter hands
    // over a reply so quickly that the next request could otherwise follow at once.
    const double waitMs = m_timing.gapLeftMs(frameGapMs());
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
    m_modbus.setByteTimeout(m_line.effectiveByteTimeoutMs());
    return true;
}

bool LibmodbusBackend::anotherReplyFollows(const ModbusRequest& request, int frameBytes)
{
    if (wireTimeMs(1) <= 0)
        return false; // Modbus TCP: transaction ids tell replies apart
    if (!m_late.isSuspect(request.slave, nowMs()))
        return false;
    // The request's own reply, if the one taken was not it, ends at the latest a turnaround
    // and the frames' wire time after sending; a quiet time more covers the gap.
    const int quietMs = recoveryQuietMs(request);
    const double ownEndMs = wireTimeMs(frameBytes) + turnaroundMs() + quietMs;
    return waitReadable(std::max(double(quietMs), ownEndMs - elapsedMs())) == 1;
}

void LibmodbusBackend::receiveStandard(const ModbusRequest& request, int timeoutMs, QByteArray* adu,
                                       ModbusResult* result)
{
    QByteArray buffer;
    int rc = m_modbus.receive(request.slave, std::max(1.0, timeoutMs - elapsedMs()), &buffer);
    int err = errno;
    // A reply complete before it could have crossed the wire is a late answer to an earlier
    // request: discarded, and the request's own answer awaited until the timeout.
    for (int early = 0; rc > 0 && early < 4; ++early) {
        *adu = buffer.left(rc);
        RtuFrame::decodeReply(request, toRtuAdu(*adu), result);
        const double tookMs = elapsedMs();
        if (result->error != ModbusError::Ok && result->error != ModbusError::Exception)
            return;
        if (!m_replyTiming.tooEarly(tookMs, wireTimeMs(m_sentBytes + int(adu->size()))))
            return;
        discardEarlyReply(request, *adu, tookMs);
        if (waitReadable(timeoutMs - elapsedMs()) != 1) {
            adu->clear();
            result->error = ModbusError::Timeout;
            result->registers.clear();
            result->message = QCoreApplication::translate("opentop::Transport",
                                                          "no reply within %1 ms (a late reply "
                                                          "to an earlier request was discarded)")
                                  .arg(timeoutMs);
            return;
        }
        buffer.clear();
        rc = m_modbus.receive(request.slave, std::max(1.0, timeoutMs - elapsedMs()), &buffer);
        err = errno;
    }
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
    if (err == EMBBADCRC)
        *adu = buffer.left(receivedLength(buffer)); // the garbled frame, for the traffic log
    if (!LibmodbusContext::replyFault(err, result))
        portFailure(err, QCoreApplication::translate("opentop::Transport", "receive failed"),
                    result);
}

void LibmodbusBackend::discardEarlyReply(const ModbusRequest& request, const QByteArray& adu,
                                         double tookMs)
{
    ++m_earlyReplies;
    const QByteArray rtu = toRtuAdu(adu);
    const quint8 sender = rtu.isEmpty() ? request.slave : quint8(rtu.at(0));
    // Its sender had an unanswered request: check its next replies for another behind them.
    m_late.suspect(sender, nowMs(), m_settings.timeoutMs);
    // It had the shape of this request: one of that shape to its sender was unanswered.
    ModbusRequest shape = request;
    shape.slave = sender;
    m_late.unanswered(shape, nowMs(), m_settings.timeoutMs);
    m_notes.noteDiscarded(rtu);
    logFrame(false, adu, request, QString(),
             QCoreApplication::translate("opentop::Transport",
                                         "late reply discarded: complete %1 ms after the request, "
                                         "where an answer needs at least %2 ms on the wire")
                 .arg(tookMs, 0, 'f', 1)
                 .arg(wireTimeMs(m_sentBytes + int(adu.size())), 0, 'f', 1),
             -1, TrafficEntry::Kind::Late);
}

void LibmodbusBackend::portFailure(int err, const QString& what, ModbusResult* result)
{
    result->error = ModbusError::PortError;
    result->message = QStringLiteral("%1: %2").arg(what, LibmodbusContext::errorText(err));
    if (LibmodbusContext::isFatal(err)) {
        qCWarning(lcTransport) << describe() << "lost:" << result->message;
        close();
        result->message +=
            QCoreApplication::translate("opentop::Transport", " (connection closed)");
    }
}

void LibmodbusBackend::discardStaleInput(const ModbusRequest& request)
{
    // Bytes waiting before we send belong to no request of ours (a late reply, noise).
    const QByteArray stale = input().readWaiting(4096);
    if (stale.isEmpty())
        return;
    m_timing.activeUntil(nowMs());
    m_notes.noteDiscarded(toRtuAdu(stale));
    m_modbus.flush();
    logFrame(
        false, stale, request, QString(),
        QCoreApplication::translate("opentop::Transport", "stale bytes discarded before sending"),
        -1, TrafficEntry::Kind::Late);
}

int LibmodbusBackend::lateReplyWindowMs(const ModbusRequest& request, int timeoutMs) const
{
    return std::max(timeoutMs, recoveryQuietMs(request));
}

double LibmodbusBackend::replyDeadlineMs(const ModbusRequest& request, int timeoutMs) const
{
    return m_timing.sentAtMs() + timeoutMs + lateReplyWindowMs(request, timeoutMs);
}

void LibmodbusBackend::recover(const ModbusRequest& request, int timeoutMs)
{
    // What came may not have been the answer to this request (a late reply to an earlier one,
    // another device, noise), so the real answer may still be on its way: swallow whatever
    // arrives until the request's late-reply window is over, or until the line has been quiet
    // for a frame time after a frame, then flush. Neither the retry nor the next request may
    // read it.
    m_late.suspect(request.slave, nowMs(), timeoutMs);
    m_late.unanswered(request, nowMs(), timeoutMs);
    const int quietMs = recoveryQuietMs(request);
    drain(request, std::max(double(quietMs), replyDeadlineMs(request, timeoutMs) - nowMs()),
          quietMs);
}

void LibmodbusBackend::awaitLateReplies(const ModbusRequest& request)
{
    const double now = nowMs();
    if (const auto wait = m_late.dueBefore(request, now, input()))
        drain(request, wait->untilMs - now, wait->quietMs);
}

void LibmodbusBackend::drain(const ModbusRequest& request, double firstWindowMs, int quietMs)
{
    const QByteArray late = input().readUntilQuiet(firstWindowMs, quietMs);
    if (!m_modbus.get())
        return;
    m_modbus.flush();
    if (late.isEmpty())
        return;
    m_timing.activeUntil(nowMs());
    m_notes.noteDiscarded(toRtuAdu(late));
    logFrame(
        false, late, request, QString(),
        QCoreApplication::translate("opentop::Transport", "late bytes discarded after an error"),
        -1, TrafficEntry::Kind::Late);
}

} // namespace opentop
