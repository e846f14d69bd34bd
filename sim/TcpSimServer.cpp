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
    for (QTcpSocket* socket : m_readers.keys())
        socket->abort();
    m_readers.clear();
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
        m_readers.insert(socket, TcpFrameReader());
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { onReadyRead(socket); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            m_readers.remove(socket);
            socket->deleteLater();
        });
    }
}

void TcpSimServer::onReadyRead(QTcpSocket* socket)
{
    TcpFrameReader& reader = m_readers[socket];
    reader.append(socket->readAll());
    TcpFrameReader::Frame request;
    for (;;) {
        const TcpFrameReader::Status status = reader.next(&request);
        if (status == TcpFrameReader::Status::NeedMore)
            return;
        if (status == TcpFrameReader::Status::Invalid) {
            qCWarning(lcSim) << "tcp: not a Modbus TCP frame, closing the connection";
            socket->disconnectFromHost();
            return;
        }
        const QByteArray adu = ModbusCrc::append(request.unitAndPdu);
        const SimOutcome outcome = m_bus->handleFrame(adu);
        // A gateway checks the line's CRC: a corrupted reply becomes no reply.
        if (outcome.reply.size() < 4 || !ModbusCrc::check(outcome.reply))
            continue;
        const QByteArray frame = TcpFrameReader::replyFrame(
            request.header, outcome.reply.left(outcome.reply.size() - 2));
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
