#pragma once

#include "transport/TrafficEntry.h"

#include <QMap>
#include <QVector>

namespace opentop {

// Counters of one drive's traffic.
struct DriveTrafficStats
{
    int slave = 0;
    int requests = 0;
    int replies = 0;    // every frame received for it, good or bad
    int timeouts = 0;   // requests without a reply
    int crcErrors = 0;  // replies with a bad CRC
    int exceptions = 0; // exception replies
    int garbled = 0;    // replies from the wrong machine number, or malformed
    int late = 0;       // frames that answered nothing asked now (TrafficEntry::Kind::Late)
    int timedReplies = 0;
    double totalMs = 0;
    double maxMs = 0;

    double meanMs() const { return timedReplies > 0 ? totalMs / timedReplies : 0.0; }
    int errors() const { return timeouts + crcErrors + exceptions + garbled; }
};

// Per-drive counters fed from traffic log entries in the order they were logged. Replies and
// events count for the drive the last request went to (a reply may carry another number); a
// late frame counts for the drive that sent it, where its first byte and CRC say so.
class TrafficStatistics
{
public:
    void add(const TrafficEntry& entry);
    void clear();

    QVector<int> slaves() const; // ascending
    // Addresses asked that never answered (a scan's empty addresses, a drive gone), ascending;
    // the broadcast address is never among them.
    QVector<int> unanswered() const;
    // `slaves` as ranges: "2–6, 8, 10–247".
    static QString rangesText(const QVector<int>& slaves);
    DriveTrafficStats drive(int slave) const;
    DriveTrafficStats total() const;

private:
    DriveTrafficStats& stats(int slave);

    QMap<int, DriveTrafficStats> m_drives;
    int m_lastRequestSlave = -1;
};

} // namespace opentop
