#pragma once

#include "ModbusRequest.h"
#include "ModbusResult.h"

#include <QString>

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

    void setTrafficLog(TrafficLog* log) { m_log = log; }
    TrafficLog* trafficLog() const { return m_log; }

protected:
    // Records a frame in the traffic log, if there is one.
    void logFrame(bool tx, const QByteArray& adu, const ModbusRequest& request,
                  const QString& summary, const QString& error, double responseMs = -1);

private:
    TrafficLog* m_log = nullptr;
};

} // namespace opentop
