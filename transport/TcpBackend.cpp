#include "transport/TcpBackend.h"

#include "transport/ModbusCrc.h"
#include "transport/RtuFrame.h"

#include <QCoreApplication>
#include <QHostAddress>
#include <QHostInfo>
#include <algorithm>
#include <cerrno>
#include <modbus.h>
#ifdef Q_OS_WIN
#include <winsock2.h>
#include <ws2tcpip.h>
#else
#include <arpa/inet.h>
#endif

namespace opentop {

namespace {

constexpr int kHeader = 7; // MBAP: transaction, protocol, length, unit id
constexpr int kMaxAdu = MODBUS_TCP_MAX_ADU_LENGTH;

} // namespace

TcpBackend::TcpBackend(const ConnectionSettings& settings)
    : LibmodbusBackend(settings)
{
}

TcpBackend::~TcpBackend()
{
    close();
}

QString TcpBackend::describe() const
{
    return settings().describe();
}

_modbus* TcpBackend::createContext()
{
    const QByteArray host = settings().host.trimmed().toUtf8();
    // modbus_new_tcp takes an IPv4 address only; names and IPv6 go through getaddrinfo.
    in_addr ipv4{};
    if (inet_pton(AF_INET, host.constData(), &ipv4) == 1)
        return modbus_new_tcp(host.constData(), settings().tcpPort);
    return modbus_new_tcp_pi(host.constData(), QByteArray::number(settings().tcpPort).constData());
}

QString TcpBackend::openErrorText(int err) const
{
    // libmodbus reports a gateway name that does not resolve as "Connection refused", which
    // sends people to the gateway's port instead of its name.
    const QString host = settings().host.trimmed();
    if (QHostAddress(host).isNull()) {
        const QHostInfo info = QHostInfo::fromName(host);
        if (info.error() != QHostInfo::NoError || info.addresses().isEmpty())
            return QCoreApplication::translate("opentop::Transport",
                                               "Cannot open %1: the name %2 was not found (%3); "
                                               "check the gateway's name, or give its address")
                .arg(describe(), host, info.errorString());
    }
    return LibmodbusBackend::openErrorText(err);
}

QByteArray TcpBackend::txAdu(const ModbusRequest& request) const
{
    const QByteArray pdu = request.pdu();
    const int length = int(pdu.size()) + 1;
    QByteArray adu(4, '\0'); // transaction id 0, protocol 0
    adu.append(char(length >> 8));
    adu.append(char(length & 0xFF));
    adu.append(char(request.slave));
    adu.append(pdu);
    return adu;
}

QByteArray TcpBackend::toRtuAdu(const QByteArray& received) const
{
    if (received.size() < kHeader)
        return received;
    return ModbusCrc::append(received.mid(kHeader - 1));
}

int TcpBackend::receivedLength(const QByteArray& buffer) const
{
    if (buffer.size() < kHeader)
        return int(buffer.size());
    const int length = (quint8(buffer.at(4)) << 8) | quint8(buffer.at(5));
    return std::clamp(6 + length, kHeader, int(std::min<qsizetype>(buffer.size(), kMaxAdu)));
}

void TcpBackend::readRawReply(const ModbusRequest& request, int timeoutMs, QByteArray* adu,
                              ModbusResult* result)
{
    // The MBAP header says how long the rest is; libmodbus would go by the function code.
    const int gapMs = settings().effectiveByteTimeoutMs();
    char chunk[kMaxAdu];
    int need = kHeader;
    while (adu->size() < need) {
        const double wait = adu->isEmpty() ? std::max(1.0, timeoutMs - elapsedMs()) : gapMs;
        const int ready = waitReadable(wait);
        if (ready < 0) {
            result->error = ModbusError::Cancelled;
            return;
        }
        if (ready == 0) {
            result->error = ModbusError::Timeout;
            result->message = QCoreApplication::translate("opentop::Transport", "reply incomplete");
            return;
        }
        const int n = readSome(chunk, need - int(adu->size()));
        if (n <= 0) {
            portFailure(n == 0 ? ECONNRESET : errno,
                        QCoreApplication::translate("opentop::Transport", "receive failed"),
                        result);
            return;
        }
        adu->append(chunk, n);
        if (need == kHeader && adu->size() >= kHeader) {
            const int length = (quint8(adu->at(4)) << 8) | quint8(adu->at(5));
            if (length < 2 || 6 + length > kMaxAdu) {
                result->error = ModbusError::MalformedReply;
                result->message =
                    QCoreApplication::translate("opentop::Transport", "MBAP length %1").arg(length);
                return;
            }
            need = 6 + length;
        }
    }
    RtuFrame::decodeReply(request, toRtuAdu(*adu), result);
}

} // namespace opentop
