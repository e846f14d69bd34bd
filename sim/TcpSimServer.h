#pragma once

#include "sim/TcpFrameReader.h"
#include "sim/WireTiming.h"

#include <QHash>
#include <QHostAddress>
#include <QObject>
#include <memory>

class QTcpServer;
class QTcpSocket;

namespace opentop {

class SimBus;

// Serves a SimBus as a Modbus TCP gateway (MBAP framing), to several clients at once. The unit
// id is the machine number on the simulated line; unit 0 is a broadcast.
class TcpSimServer : public QObject
{
    Q_OBJECT
public:
    TcpSimServer(std::shared_ptr<SimBus> bus, const WireTiming& timing, bool wireTiming,
                 QObject* parent = nullptr);
    ~TcpSimServer() override;

    // Port 0 picks a free port (see port()).
    bool listen(const QHostAddress& address, quint16 port, QString* error);
    void close();
    QHostAddress address() const;
    quint16 port() const;

private:
    void onNewConnection();
    void onReadyRead(QTcpSocket* socket);

    std::shared_ptr<SimBus> m_bus;
    WireTiming m_timing;
    bool m_wireTiming;
    QTcpServer* m_server;
    QHash<QTcpSocket*, TcpFrameReader> m_readers;
};

} // namespace opentop
