#pragma once

#include "model/bus/ScanReasks.h"
#include "model/bus/ScanWaits.h"
#include "model/session/DeviceInfo.h"
#include "transport/LineFormat.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QVector>

namespace opentop {

class DeviceIdentifier;
class ModbusClient;
class ProfileRegistry;
struct ConnectionSettings;
struct ModbusResult;

// Finds the drives on a bus: asks every machine number of a range with each profile's identify
// read (DeviceIdentifier decodes the replies), one transaction at a time, asynchronously, while
// it owns the bus (ModbusClient::holdPolling: polls wait). An empty address costs one short wait
// for the first byte; one that answered gets a whole reply's wait (ScanWaits), a second question
// when its frames are garbled (a duplicate machine number?), more when its reply came late or it
// could not be identified (ScanReasks), and is then reported, never dropped
// (docs/communication.md, "Scans").
class BusScanner : public QObject
{
    Q_OBJECT
public:
    // The waits' limits and the answer budget they allow a drive (ScanWaits).
    static constexpr int kMinWaitMs = ScanWaits::kMinWaitMs;
    static constexpr int kMaxWaitMs = ScanWaits::kMaxWaitMs;
    static constexpr double kAnswerBudgetMs = ScanWaits::kAnswerBudgetMs;
    // Times an address that answered is asked again before it is reported unidentified.
    static constexpr int kIdentifyRetries = 3;
    // How far back a garbled frame makes silent addresses suspect: several waits, at least this
    // (a re-ask costs four waits, and garbled frames are rare on a sound line).
    static constexpr int kSuspectWindowMs = 400; // a busy machine delays replies that long

    BusScanner(ModbusClient* client, const ProfileRegistry& registry, QObject* parent = nullptr);
    ~BusScanner() override;

    // Per-address wait for the first byte of a reply, and for a whole reply (ScanWaits).
    static int defaultWaitMs(const ConnectionSettings& settings, int adapterLatencyMs = 0)
    {
        return ScanWaits::defaultWaitMs(settings, adapterLatencyMs);
    }
    static int wholeReplyWaitMs(const ConnectionSettings& settings, int firstByteWaitMs,
                                int replyBytes)
    {
        return ScanWaits::wholeReplyWaitMs(settings, firstByteWaitMs, replyBytes);
    }

    // Range and wait for the next start(); waitMs 0 uses defaultWaitMs().
    void setRange(int from, int to);
    void setWaitMs(int ms) { m_waits.setWaitMs(ms); }
    // The format every request of the next start() goes out in (ScanWaits::setLine).
    void setLine(const LineFormat& format) { m_waits.setLine(format); }
    LineFormat line() const { return m_waits.line(); }
    int from() const { return m_from; }
    int to() const { return m_to; }
    int waitMs() const { return m_waits.waitFor(0); }

    void start();
    // Stops between transactions: the one on the wire completes, then finished() follows.
    void cancel();
    bool isRunning() const { return m_running; }
    bool wasCancelled() const { return m_cancelled; }
    // Why the scan stopped early (the port failed); empty otherwise.
    QString error() const { return m_error; }

    // Machine numbers finished so far (from() .. from() + scannedCount() - 1).
    int scannedCount() const { return m_done; }
    int total() const { return m_to - m_from + 1; }
    int requestsSent() const { return m_requests; }
    // Drives found only when asked again with a longer wait: a reply from them came after their
    // wait, or a garbled frame came soon after they were asked (a late reply colliding with a
    // later request).
    int lateAnswers() const { return m_lateAnswers; }
    // The addresses among `devices` that answered but could not be identified.
    static QVector<int> unidentified(const QVector<DeviceInfo>& devices);
    double elapsedMs() const;
    // Every address that answered, in machine number order.
    QVector<DeviceInfo> devices() const { return m_devices; }

signals:
    void progress(int done, int total, int slave);
    void found(const opentop::DeviceInfo& info);
    // `slave` answered, but its identification failed: it is asked again (`attempt` of
    // kIdentifyRetries) before the scan gives up and reports it.
    void identificationRetry(int slave, int attempt, int attempts);
    void finished(const QVector<opentop::DeviceInfo>& devices);

private:
    void askProfile(int profileIndex, bool confirming);
    void handleReply(int profileIndex, bool confirming, const ModbusResult& result);
    void noteLateAnswer(const ModbusResult& result);
    void askAgainLater(int slave);
    void askRecentAgain();
    // Whether `slave` has been reported (found(), in devices()).
    bool reported(int slave) const;
    // The address answered before; its identification has just failed.
    DeviceInfo identificationFailed(DeviceInfo info);
    void addressDone(DeviceInfo info);
    void nextAddress();
    void finish();

    ModbusClient* m_client;
    QPointer<ModbusClient> m_held; // holding its polling while running
    const ProfileRegistry& m_registry;
    DeviceIdentifier* m_identifier;
    int m_from = 1;
    int m_to = 247;
    ScanWaits m_waits;
    int m_cursor = 1;       // the next address of the pass through the range
    int m_slave = 0;        // the address being asked
    double m_askedAtMs = 0; // when m_slave's first request went out
    bool m_reasking = false;
    ScanReasks m_reasks{kIdentifyRetries};
    int m_lateAnswers = 0;
    int m_done = 0;
    int m_requests = 0;
    quint64 m_pendingId = 0; // the request of ours that is queued or on the wire
    quint64 m_handledId = 0; // the last of ours handed to handleReply()
    bool m_running = false;
    bool m_cancelled = false;
    bool m_cancelRequested = false;
    QString m_error;
    QVector<DeviceInfo> m_devices;
    QElapsedTimer m_timer;
    double m_elapsedMs = 0;
};

} // namespace opentop
