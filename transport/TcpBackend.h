#pragma once

#include "transport/LibmodbusBackend.h"

namespace opentop {

// Modbus TCP to a gateway or a TCP device through libmodbus; the unit id is the request's slave.
// Requests go out with transaction id 0 (modbus_send_raw_request does not set one), so stale
// replies are kept apart by draining, as on a serial line.
class TcpBackend : public LibmodbusBackend
{
public:
    explicit TcpBackend(const ConnectionSettings& settings);
    ~TcpBackend() override;

    QString describe() const override;
    int defaultTurnaroundMs() const override { return 10; }

protected:
    _modbus* createContext() override;
    QString openErrorText(int err) const override;
    QByteArray txAdu(const ModbusRequest& request) const override;
    QByteArray toRtuAdu(const QByteArray& received) const override;
    int receivedLength(const QByteArray& buffer) const override;
    void readRawReply(const ModbusRequest& request, int timeoutMs, QByteArray* adu,
                      ModbusResult* result) override;
    double wireTimeMs(int) const override { return 0; }
    int recoveryQuietMs(const ModbusRequest&) const override { return 20; }
};

} // namespace opentop
