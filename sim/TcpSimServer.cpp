#include "sim/TcpSimServer.h"

#include "sim/SimBus.h"
#include "sim/SimLog.h"
#include "transport/ModbusCrc.h"

#include <QCoreApplication>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

namespace opentop {

namespace {

constexpr int kMbapHeader = 7; // transaction(2) protocol(2) length(2) unit(1)

quint16 word(const QByteArray& bytes, int at)
{
    return quint16((quint8(bytes.at(at)) << 8) | quint8(bytes.at(at + 1)));
}

} // namespace

TcpSimServer::TcpSimServer(std::shared_ptr<SimBus> bus, const WireTiming& timing, bool wireTiming,
                           QObject* parent)
    : QObject(parent)
    , m_bus(std::move(bus))
    , m_timing(timing)
    , m_wireTiming(wireTiming)
    , m_server(new QTcpServer(this))
{
    connect(m_server, &QTcpServer::newConnection, this, &TcpSimServer::onNewConnection);
}

TcpSimServer::~TcpSimServer()
{
    close();
}

bool TcpSimServer::listen(const QHostAddress& address, quint16 port, QString* error)
{
    if (!m_server->listen(address, port)) {
        if (error)
            *error =
                QCoreApplication::translate("opentop::TcpSimServer", "cannot listen on %1:%2: %3")
                    .arg(address.toString())
                    .arg(port)
                    .arg(m_server->errorString());
        return false;
    }
    qCInfo(lcSim) << "serving" << m_bus->spec() << "on tcp" << address.toString() << this->port();
    return true;
}

void TcpSimServer::close()
{
    m_server->close();
    for (QTcpSocket* socket : m_buffers.keys())
        socket->abort();
    m_buffers.clear();
}

QHostAddress TcpSimServer::address() const
{
    return m_server->serverAddress();
}

quint16 TcpSimServer::port() const
{
    return m_server->serverPort();
}

void TcpSimServer::onNewConnection()
{
    while (QTcpSocket* socket = m_server->nextPendingConnection()) {
        m_buffers.insert(socket, QByteArray());
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { onReadyRead(socket); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            m_buffers.remove(socket);
            socket->deleteLater();
        });
    }
}

void TcpSimServer::onReadyRead(QTcpSocket* socket)
{
    QByteArray& buffer = m_buffers[socket];
    buffer.append(socket->readAll());
    while (buffer.size() >= kMbapHeader) {
        const quint16 length = word(buffer, 4);
        if (word(buffer, 2) != 0 || length < 2 || length > 254) {
            qCWarning(lcSim) << "tcp: not a Modbus TCP frame, closing the connection";
            buffer.clear();
            socket->disconnectFromHost();
            return;
        }
        if (buffer.size() < 6 + length)
            return;
        const QByteArray header = buffer.left(6);
        const QByteArray unitAndPdu = buffer.mid(6, length);
        buffer.remove(0, 6 + length);

        const QByteArray adu = ModbusCrc::append(unitAndPdu);
        const SimOutcome outcome = m_bus->handleFrame(adu);
        // A gateway checks the line's CRC: a corrupted reply becomes no reply.
        if (outcome.reply.size() < 4 || !ModbusCrc::check(outcome.reply))
            continue;
        const QByteArray replyPdu = outcome.reply.left(outcome.reply.size() - 2);
        QByteArray frame = header.left(4);
        frame.append(char(replyPdu.size() >> 8));
        frame.append(char(replyPdu.size() & 0xFF));
        frame.append(replyPdu);
        double delay = outcome.delayMs;
        if (m_wireTiming)
            delay += m_timing.replyDelayMs(adu.size(), outcome.reply.size());
        QPointer<QTcpSocket> target(socket);
        if (delay < 0.5) {
            socket->write(frame);
        } else {
            QTimer::singleShot(int(delay + 0.5), Qt::PreciseTimer, this, [target, frame] {
                if (target)
                    target->write(frame);
            });
        }
    }
}

} // namespace opentop
