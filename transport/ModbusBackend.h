#pragma once

#include "transport/ModbusRequest.h"
#include "transport/ModbusResult.h"
#include "transport/SerialLineReport.h"
#include "transport/TrafficEntry.h"

#include <QString>
#include <atomic>

namespace opentop {

class TrafficLog;

// A synchronous Modbus master for one connection. Used by one thread only (the bus worker),
// because a libmodbus context is not thread-safe. One call is one attempt; retries are the
// client's business.
class ModbusBackend
{
public:
    virtual ~ModbusBackend();

    virtual bool open(QString* error) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    // Sends `request` and waits for its reply for at most timeoutMs. A broadcast (slave 0)
    // returns Ok without waiting for a reply, after keeping the bus quiet for the turnaround.
    virtual ModbusResult transact(const ModbusRequest& request, int timeoutMs) = 0;
    virtual QString describe() const = 0;
    // What the serial driver accepted when the port was opened (RS-485 direction, low
    // latency); empty for a backend without a serial line. Worker thread only.
    virtual SerialLineReport lineReport() const { return {}; }

    // May be called from any thread (the pointer is atomic).
    void setTrafficLog(TrafficLog* log) { m_log = log; }
    TrafficLog* trafficLog() const { return m_log; }

    // Set by the client worker: once *flag is true, waits inside transact() end early with
    // Cancelled, so that the worker can stop within a bounded time.
    void setInterruptFlag(const std::atomic<bool>* flag) { m_interrupt = flag; }
    bool interrupted() const { return m_interrupt && m_interrupt->load(); }

    // One-line meaning of a reply for logs: "→ 1500", "echo 0x0003 = 1",
    // "exception 02 Illegal data address".
    static QString describeReply(const ModbusRequest& request, const ModbusResult& result);

protected:
    // Records a frame in the traffic log, if there is one.
    void logFrame(bool tx, const QByteArray& adu, const ModbusRequest& request,
                  const QString& summary, const QString& error, double responseMs = -1,
                  TrafficEntry::Kind kind = TrafficEntry::Kind::Frame);
    // Records a reply (or its absence) with the slave and function it really carried.
    void logReply(const QByteArray& adu, int slave, int function, const ModbusRequest& request,
                  const ModbusResult& result);
    // Records something that is not a frame, e.g. "no reply within 200 ms".
    void logEvent(const ModbusRequest& request, const QString& summary, const QString& error);
    void logEntry(TrafficEntry entry, const ModbusRequest* request);
    // Sleeps in short slices; false when interrupted first.
    bool sleepInterruptible(double ms) const;

private:
    std::atomic<TrafficLog*> m_log{nullptr};
    const std::atomic<bool>* m_interrupt = nullptr;
};

} // namespace opentop
