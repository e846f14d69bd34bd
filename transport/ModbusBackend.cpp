#include "transport/ModbusBackend.h"

#include "transport/DeviceIdentification.h"
#include "transport/TrafficLog.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QStringList>
#include <QThread>
#include <algorithm>

namespace opentop {

namespace {

QString hex4(quint16 value)
{
    return QStringLiteral("0x") +
           QString::number(value, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

} // namespace

ModbusBackend::~ModbusBackend() = default;

QString ModbusBackend::describeReply(const ModbusRequest& request, const ModbusResult& result)
{
    if (result.error != ModbusError::Ok)
        return result.errorText();
    if (request.raw) {
        DeviceIdentification id;
        if (request.function == ModbusRequest::EncapsulatedInterface &&
            DeviceIdentification::parse(result.rawData, &id)) {
            QStringList texts;
            for (auto it = id.objects.cbegin(); it != id.objects.cend(); ++it)
                texts << id.text(it.key());
            return QStringLiteral("→ ") + texts.join(QStringLiteral(" | "));
        }
        return QCoreApplication::translate("opentop::Transport", "→ %1 bytes")
            .arg(result.rawData.size());
    }
    if (request.isRead()) {
        QStringList values;
        for (int i = 0; i < result.registers.size() && i < 8; ++i)
            values << QString::number(result.registers[i]);
        if (result.registers.size() > 8)
            values << QStringLiteral("…");
        return QStringLiteral("→ ") + values.join(QStringLiteral(", "));
    }
    if (request.function == ModbusRequest::WriteSingle)
        return QCoreApplication::translate("opentop::Transport", "echo %1 = %2")
            .arg(hex4(request.address))
            .arg(request.values.value(0));
    return QCoreApplication::translate("opentop::Transport", "echo %1 ×%2")
        .arg(hex4(request.address))
        .arg(request.count);
}

void ModbusBackend::logFrame(bool tx, const QByteArray& adu, const ModbusRequest& request,
                             const QString& summary, const QString& error, double responseMs,
                             TrafficEntry::Kind kind)
{
    TrafficEntry entry;
    entry.direction = tx ? TrafficEntry::Direction::Tx : TrafficEntry::Direction::Rx;
    entry.slave = request.slave;
    entry.function = request.function;
    entry.bytes = adu;
    entry.summary = summary;
    entry.error = error;
    entry.responseMs = tx ? -1 : responseMs;
    entry.kind = kind;
    logEntry(entry, &request);
}

void ModbusBackend::logReply(const QByteArray& adu, int slave, int function,
                             const ModbusRequest& request, const ModbusResult& result)
{
    TrafficEntry entry;
    entry.direction = TrafficEntry::Direction::Rx;
    entry.slave = quint8(slave >= 0 ? slave : request.slave);
    entry.function = quint8(function >= 0 ? function : request.function);
    entry.bytes = adu;
    entry.summary = describeReply(request, result);
    // An exception is a valid answer; its meaning is already in the summary.
    if (result.error != ModbusError::Ok && result.error != ModbusError::Exception)
        entry.error = result.errorText();
    entry.responseMs = result.elapsedMs;
    logEntry(entry, &request);
}

void ModbusBackend::logEvent(const ModbusRequest& request, const QString& summary,
                             const QString& error)
{
    TrafficEntry entry;
    entry.direction = TrafficEntry::Direction::Event;
    entry.slave = request.slave;
    entry.function = request.function;
    entry.summary = summary;
    entry.error = error;
    logEntry(entry, &request);
}

void ModbusBackend::logEntry(TrafficEntry entry, const ModbusRequest* request)
{
    if (TrafficLog* log = m_log.load())
        log->append(std::move(entry), request);
}

bool ModbusBackend::sleepInterruptible(double ms) const
{
    QElapsedTimer timer;
    timer.start();
    for (;;) {
        if (interrupted())
            return false;
        const double left = ms - double(timer.nsecsElapsed()) / 1e6;
        if (left <= 0)
            return true;
        QThread::usleep(static_cast<unsigned long>(std::min(left, 20.0) * 1000));
    }
}

} // namespace opentop
