#pragma once

#include "sim/ReplyScheduler.h"
#include "sim/WireTiming.h"

#include <QByteArray>
#include <QObject>
#include <QTimer>
#include <memory>

class QLockFile;
class QSocketNotifier;

namespace opentop {

class SimBus;

// Serves a SimBus on a pseudo-terminal: clients (libmodbus RTU, mbpoll) open the slave path as
// if it were a serial port. Requests are framed by length per function code, unknown functions
// by a silence gap; frames with a bad CRC are ignored, as on a line.
class PtySimServer : public QObject
{
    Q_OBJECT
public:
    PtySimServer(std::shared_ptr<SimBus> bus, const WireTiming& timing, bool wireTiming,
                 QObject* parent = nullptr);
    ~PtySimServer() override;

    // Opens the pty; with a linkPath, also a symlink to the slave (an existing symlink is
    // replaced, any other file is refused). The link is locked first (QLockFile "<link>.lock",
    // held until close()): while another live simulator holds it, open() refuses naming its
    // PID (linkHolderPid()); a lock left by a simulator that is gone is taken over.
    bool open(const QString& linkPath, QString* error);
    void close();
    // The PID of the simulator that holds the link, when the last open() was refused for it.
    qint64 linkHolderPid() const { return m_linkHolderPid; }
    // The adapter pulled out: the pty is closed under its client (reads and writes fail) and
    // the symlink removed, as /dev/ttyUSB0 vanishes. The devices keep their state.
    void unplug();
    // Plugged in again: a new pty behind the same symlink.
    bool replug(QString* error);
    bool isOpen() const { return m_master >= 0; }
    QString slavePath() const { return m_slavePath; }
    QString linkPath() const { return m_linkPath; }

    // With wire timing: the line is one half-duplex pair, as RS-485 is. A request that overlaps
    // a reply on the wire garbles both (the reply reaches the client with a bad CRC, the
    // request is not answered), and a request less than 3.5 characters after the last reply
    // is not taken as a frame of its own (DBU manual 11-1: no reply then).
    void setHalfDuplex(bool on) { m_halfDuplex = on; }
    // Requests lost to the half-duplex rules above, for the console's stats.
    int collisions() const { return m_collisions; }
    int gapViolations() const { return m_gapViolations; }

    // Length of the request at the start of `buffer`: 0 while more bytes are needed, -1 when
    // the function code gives no length (framing by silence).
    static int requestLength(const QByteArray& buffer);

private:
    bool lockLink(const QString& linkPath, QString* error);
    void closePty(); // close() but the link stays locked (unplugged)
    void onReadable();
    void onSilence();
    void processBuffer();
    void dispatch(const QByteArray& frame);
    void send(const QByteArray& reply);
    // Half-duplex rules for a request arriving now; false: it is lost.
    bool lineAccepts(const QByteArray& frame, qint64 nowNs);
    WireTiming frameTiming() const;

    std::shared_ptr<SimBus> m_bus;
    WireTiming m_timing;
    bool m_wireTiming;
    int m_master = -1;
    int m_slave = -1;
    QString m_slavePath;
    QString m_linkPath;
    QString m_unpluggedLink; // the symlink to restore on replug
    std::unique_ptr<QLockFile> m_linkLock;
    qint64 m_linkHolderPid = 0;
    QSocketNotifier* m_notifier = nullptr;
    QByteArray m_buffer;
    LineFormat m_frameLine; // the client's format as the frame in m_buffer began
    QTimer m_silence;
    ReplyScheduler* m_replies;
    bool m_halfDuplex = false;
    qint64 m_lastReplyEndNs = 0;
    int m_collisions = 0;
    int m_gapViolations = 0;
};

} // namespace opentop
