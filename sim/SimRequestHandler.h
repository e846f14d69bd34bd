#pragma once

#include "sim/SimDevice.h"

#include <QByteArray>
#include <QVector>

namespace opentop {

struct ModbusRequest;

// The generic Modbus request handling of one simulated device: checks a request's format and
// addresses against the device's register layout, checks written values against the profile
// on a copy of the registers before any of them changes, and builds the reply or exception ADU.
// What a family adds comes in through the device's hooks.
class SimRequestHandler
{
public:
    explicit SimRequestHandler(SimDevice& device);

    // See SimDevice::handle and SimDevice::busyReply.
    QByteArray handle(const ModbusRequest& request, qint64 nowMs, bool addressedDirectly);
    QByteArray busyReply(const ModbusRequest& request, qint64 nowMs);

private:
    SimError doRead(const ModbusRequest& request, QVector<quint16>* values) const;
    SimError doWrite(const ModbusRequest& request, qint64 nowMs);
    QByteArray exceptionAdu(quint8 function, SimError error) const;
    QByteArray adu(const QByteArray& pdu) const;

    SimDevice& m_device;
};

} // namespace opentop
