#pragma once

#include "transport/ConnectionSettings.h"
#include "transport/LateReplyWatch.h"
#include "transport/LibmodbusContext.h"
#include "transport/LineInput.h"
#include "transport/LineNotes.h"
#include "transport/LineTiming.h"
#include "transport/ModbusBackend.h"
#include "transport/ReplyTiming.h"

namespace opentop {

// What RTU and TCP share on top of libmodbus: every request goes out through
// modbus_send_raw_request (so the traffic log shows the exact bytes), standard replies come
// back through modbus_receive_confirmation, raw replies are read from the socket
// (LibmodbusContext holds the context, LineInput reads the socket). Errors are classified from
// errno. RTU has no transaction ids, so after an error the master resynchronises before
// anything else goes out: it reads and discards until the line has fallen silent, that is
// until the late-reply window of the failed request has passed (a reply can still start up to
// one more timeout after the timeout, see lateReplyWindowMs()) and nothing has arrived for a
// frame time, then flushes. Only then can a late reply not be taken for the answer to the retry
// or the next request. After a timeout with nothing received that wait is deferred: it happens
// before the next request to the same slave (or a broadcast, or when bytes are arriving), while
// a request to another slave goes out at once, because a late reply carries its sender's id and
// is then rejected as a wrong-slave reply. This keeps scans of empty addresses at one wait each
// (LateReplyWatch remembers who may still answer). On a half-duplex line a reply still on the
// wire collides with any request, though: LineNotes. LineTiming keeps the gaps between frames.
class LibmodbusBackend : public ModbusBackend
{
public:
    ~LibmodbusBackend() override;

    bool open(QString* error) override;
    void close() override;
    bool isOpen() const override;
    ModbusResult transact(const ModbusRequest& request, int timeoutMs) override;

    const ConnectionSettings& settings() const { return m_settings; }
    // The port's settings with the format in force now: the port's own until a request
    // carries another (ModbusRequest::line). Timings (gaps, byte timeout) follow it.
    const ConnectionSettings& lineSettings() const { return m_line; }
    // Bus silence after a broadcast; < 0 restores the default.
    void setTurnaroundMs(int ms) { m_timing.setTurnaroundMs(ms); }
    int turnaroundMs() const { return m_timing.turnaroundMs(defaultTurnaroundMs()); }
    virtual int defaultTurnaroundMs() const = 0;
    // Silence kept between the end of the last frame on the line and the next request (the
    // Modbus RTU inter-frame gap); < 0 restores the default, 0 keeps none (benchmarks that
    // compare with a plain loop on a pty).
    void setFrameGapMs(double ms) { m_timing.setFrameGapMs(ms); }
    double frameGapMs() const { return m_timing.frameGapMs(defaultFrameGapMs()); }
    virtual double defaultFrameGapMs() const { return 0; }

protected:
    explicit LibmodbusBackend(const ConnectionSettings& settings);

    virtual _modbus* createContext() = 0;
    virtual QString openErrorText(int err) const;
    // The ADU exactly as libmodbus puts it on the wire.
    virtual QByteArray txAdu(const ModbusRequest& request) const = 0;
    // A received ADU as an RTU frame (id + PDU + CRC), for RtuFrame::decodeReply.
    virtual QByteArray toRtuAdu(const QByteArray& received) const = 0;
    // Length of the frame libmodbus read into `buffer` (for logging a rejected reply).
    virtual int receivedLength(const QByteArray& buffer) const = 0;
    // Reads a raw reply whose first byte is waiting; fills adu (as received) and result.
    virtual void readRawReply(const ModbusRequest& request, int timeoutMs, QByteArray* adu,
                              ModbusResult* result) = 0;
    // Time the line needs for `bytes` bytes (0 for TCP) and quiet time after an error.
    virtual double wireTimeMs(int bytes) const = 0;
    virtual int recoveryQuietMs(const ModbusRequest& request) const = 0;
    // How long after its timeout a reply to a request may still start: as long as the timeout
    // itself (a device twice as slow as the wait), and at least the quiet time. A reply later
    // than that is beyond what a master without transaction ids can tell apart.
    virtual int lateReplyWindowMs(const ModbusRequest& request, int timeoutMs) const;
    // Puts the open port into `format`, between transactions (the line is quiet); false with
    // *error when it cannot. This one refuses: only a serial line has a format to switch.
    virtual bool applyLineFormat(const LineFormat& format, QString* error);

    // The connection's descriptor read directly (LineInput).
    LineInput input() const { return LineInput(m_modbus, *this); }
    int waitReadable(double timeoutMs) const { return input().waitReadable(timeoutMs); }
    int readSome(char* buffer, int maximum) const { return input().readSome(buffer, maximum); }
    // Fills `result` with a PortError; closes the backend when the error is fatal.
    void portFailure(int err, const QString& what, ModbusResult* result);
    double elapsedMs() const { return m_timing.elapsedMs(); }
    // Who may still answer a request given up on, for the line's next user, and the same
    // from the line's previous user (LateReplyJournal); times on clockMs()'s clock.
    QVector<LateReplyWatch::Suspect> lateSuspects() { return m_late.suspects(nowMs()); }
    void suspectUntil(const LateReplyWatch::Suspect& suspect) { m_late.suspectUntil(suspect); }
    double clockMs() const { return nowMs(); }
    _modbus* context() const { return m_modbus.get(); }
    const LibmodbusContext& modbusContext() const { return m_modbus; }
    int descriptor() const { return m_modbus.socket(); }

private:
    // One request and its reply (transact() reads again where a reply is ambiguous).
    ModbusResult exchange(const ModbusRequest& request, int timeoutMs);
    void receiveStandard(const ModbusRequest& request, int timeoutMs, QByteArray* adu,
                         ModbusResult* result);
    void discardStaleInput(const ModbusRequest& request);
    // A reply complete sooner than the wire allows (ReplyTiming): logged and counted as late.
    void discardEarlyReply(const ModbusRequest& request, const QByteArray& adu, double tookMs);
    // After a reply that was garbled, foreign, malformed or incomplete: waits until the failed
    // request's late-reply window has passed and the line is quiet (see the class comment).
    void recover(const ModbusRequest& request, int timeoutMs);
    // Until when a reply to the request sent last may still start.
    double replyDeadlineMs(const ModbusRequest& request, int timeoutMs) const;
    // Reads and discards until the line has been quiet for `quietMs` (the first window may be
    // shorter), then flushes.
    void drain(const ModbusRequest& request, double firstWindowMs, int quietMs);
    // Before sending: completes a deferred drain where the id check cannot protect us.
    void awaitLateReplies(const ModbusRequest& request);
    // After a complete reply from a suspect (LateReplyWatch; never on TCP): true when more
    // bytes come before the request's own reply could have ended, so that the reply taken may
    // have been a late answer to an earlier request.
    bool anotherReplyFollows(const ModbusRequest& request, int frameBytes);
    double nowMs() const { return m_timing.nowMs(); }
    // Waits until the line has been silent for the frame gap; false when interrupted.
    bool keepFrameGap();
    // Before a request in another format than the line's: the gap after the last frame is
    // kept at the old rate, then the port is switched (applyLineFormat), and the caller keeps
    // the gap again at the new rate. False (and `result` filled) when it failed.
    bool switchLine(const LineFormat& format, ModbusResult* result);

    ConnectionSettings m_settings;
    ConnectionSettings m_line; // m_settings in the format in force
    LibmodbusContext m_modbus;
    bool m_open = false;
    LineTiming m_timing;       // the clock of every time below, the gaps kept
    LateReplyWatch m_late;     // who may still answer a failed request
    LineNotes m_notes;         // what was discarded, a held line
    ReplyTiming m_replyTiming; // whether a reply came sooner than the wire allows
    int m_sentBytes = 0;       // the current request's frame on the wire
    int m_earlyReplies = 0;    // replies discarded as too early for the current request
};

} // namespace opentop
