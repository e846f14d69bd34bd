#pragma once

#include "transport/ConnectionSettings.h"

#include <QHash>
#include <QObject>
#include <functional>
#include <memory>

namespace opentop {

class ModbusClient;

// A connection being opened while the working one stays: a mistyped port or a gateway that
// does not answer must not cost the bus one was working on. Once the new client is open it is
// handed over (`adopt`); when it cannot be opened, `refuse` says why and the working one stays.
class PendingConnection : public QObject
{
    Q_OBJECT
public:
    using Adopt =
        std::function<void(std::unique_ptr<ModbusClient> client, const ConnectionSettings& settings,
                           const QHash<int, QString>& knownTypes)>;
    using Refuse = std::function<void(const ConnectionSettings& settings, const QString& why)>;

    PendingConnection(Adopt adopt, Refuse refuse);
    ~PendingConnection() override;

    // Whether the working connection at `working` can stay while `next` is opened: not when
    // `next` reopens the same serial port (other settings), which is ours until it is closed.
    static bool canWait(const ConnectionSettings& working, const ConnectionSettings& next);
    // Opens `client`; adopt or refuse follows.
    void open(std::unique_ptr<ModbusClient> client, const ConnectionSettings& settings,
              const QHash<int, QString>& knownTypes);
    // Gives up the connection being opened, if any.
    void drop();
    bool isOpening() const { return m_client != nullptr; }

private:
    Adopt m_adopt;
    Refuse m_refuse;
    std::unique_ptr<ModbusClient> m_client;
    ConnectionSettings m_settings;
    QHash<int, QString> m_types;
};

} // namespace opentop
