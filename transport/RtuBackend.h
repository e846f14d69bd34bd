#pragma once

#include "transport/LateReplyJournal.h"
#include "transport/LibmodbusBackend.h"
#include "transport/PortLock.h"
#include "transport/SerialLineSetup.h"

#include <memory>

namespace opentop {

// Modbus RTU on a serial device (or a pty) through libmodbus. The libmodbus context is created
// in open() and freed in close(): both must run on the thread that calls transact().
class RtuBackend : public LibmodbusBackend
{
public:
    explicit RtuBackend(const ConnectionSettings& settings);
    ~RtuBackend() override;

    // Locks the port first (PortLock: flock, UUCP lock file, then exclusive mode), so that a
    // second OpenTOP or another program on the same port is refused, naming the holder, before
    // anything touches the line; the lock goes with the port (and with the process). Then sets
    // the line's RS-485 direction control and low latency (SerialLineSetup): what the driver
    // took is lineReport(); what it refused does not fail the open.
    bool open(QString* error) override;
    // Puts the driver's RS-485 and low-latency settings back as they were found.
    void close() override;
    QString describe() const override;
    SerialLineReport lineReport() const override { return m_lineReport; }
    // The T-net manual's broadcast gap T2 > C3.5 + 5 ms (DBU manual 11-1): the next whole
    // millisecond above 3.5 character times + 5 ms, at least 10 ms (the manual's C3.5 is 4.0 ms at
    // 9600 bit/s and 2.5 ms at 19200, more than 3.5 character times of 8N1).
    int defaultTurnaroundMs() const override;
    // The Modbus RTU inter-frame gap: 3.5 character times, 1.75 ms above 19200 bit/s (Modbus
    // over serial line 2.5.1.1). See erratum DBU-30 for the manual's rounder figures.
    double defaultFrameGapMs() const override;
    // Format switches made since the port was opened, and their mean cost in µs (tcdrain +
    // tcsetattr; the gap at the new rate is kept on top of it).
    int lineSwitches() const { return m_line.switchCount(); }
    double meanSwitchMicros() const;

protected:
    _modbus* createContext() override;
    QString openErrorText(int err) const override;
    QByteArray txAdu(const ModbusRequest& request) const override;
    QByteArray toRtuAdu(const QByteArray& received) const override;
    int receivedLength(const QByteArray& buffer) const override;
    void readRawReply(const ModbusRequest& request, int timeoutMs, QByteArray* adu,
                      ModbusResult* result) override;
    double wireTimeMs(int bytes) const override;
    int recoveryQuietMs(const ModbusRequest& request) const override;
    bool applyLineFormat(const LineFormat& format, QString* error) override;
    // The driver calls go through this (a test wraps it to see their order and time).
    virtual std::unique_ptr<SerialDriver> makeDriver();

private:
    // Who may still answer a request the line's previous or next user gave up on.
    LateReplyJournal journal() const;

    PortLock m_lock;
    SerialLineSetup m_line;
    SerialLineReport m_lineReport;
};

} // namespace opentop
