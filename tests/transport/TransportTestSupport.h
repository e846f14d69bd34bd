#pragma once

// Helpers for the transport tests: event-loop waits, a pty pair with a scripted device on the
// master side, and a tiny Modbus TCP server.

#include "transport/MockBackend.h"
#include "transport/ModbusClient.h"

#include <QByteArray>
#include <QString>
#include <atomic>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace opentop::test {

// Processes Qt events until `done` returns true or `timeoutMs` passes; returns done().
bool waitUntil(const std::function<bool()>& done, int timeoutMs = 2000);

// A well-behaved device for MockBackend: reads return their address (+i), writes are echoed,
// other functions get exception 01.
QByteArray echoDevice(const QByteArray& adu);

// A ModbusClient on a MockBackend; `mock` stays valid while `client` lives.
struct MockClient
{
    MockBackend* mock = nullptr;
    std::unique_ptr<ModbusClient> client;

    explicit MockClient(MockBackend::Handler handler, const ConnectionSettings& settings = {},
                        bool open = true);
};

// Number of this process' descriptors open on `path` (to see that a port was closed).
int openDescriptorsOn(const QString& path);

// What a scripted device sends back for one request.
struct Answer
{
    QByteArray bytes; // empty: stay silent
    int delayMs = 0;  // before sending
    // Sent after `bytes`, after `secondDelayMs` (a reply split in two, or a second frame).
    QByteArray second;
    int secondDelayMs = 0;
};
using Script = std::function<Answer(const QByteArray& request)>;

// openpty() pair: the client opens `path()`; a thread plays the devices on the master side,
// framing requests by RtuFrame::expectedRequestLength.
class PtyDevice
{
public:
    PtyDevice();
    ~PtyDevice();
    QString path() const { return m_path; }
    void start(Script script);
    void stop();
    // Simulates an unplugged adapter: the client side then reads EIO.
    void closeMaster();
    std::vector<QByteArray> requests() const;

private:
    void run();

    int m_master = -1;
    int m_slave = -1;
    QString m_path;
    Script m_script;
    std::thread m_thread;
    std::atomic<bool> m_stop{false};
    mutable std::mutex m_mutex;
    std::vector<QByteArray> m_requests;
};

// Modbus TCP server on 127.0.0.1 (ephemeral port), one connection at a time. The script gets
// and returns whole TCP ADUs (MBAP header included).
class TcpDevice
{
public:
    TcpDevice();
    ~TcpDevice();
    int port() const { return m_port; }
    void start(Script script);
    void stop();
    // Closes the accepted connection (the gateway went away).
    void dropConnection();
    std::vector<QByteArray> requests() const;

private:
    void run();

    int m_listen = -1;
    std::atomic<int> m_connection{-1};
    int m_port = 0;
    Script m_script;
    std::thread m_thread;
    std::atomic<bool> m_stop{false};
    mutable std::mutex m_mutex;
    std::vector<QByteArray> m_requests;
};

} // namespace opentop::test
