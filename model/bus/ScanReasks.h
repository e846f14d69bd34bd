#pragma once

#include <QHash>
#include <QSet>
#include <QVector>

namespace opentop {

// The addresses a scan asks again, with a long wait, before it goes on through its range, and
// the times each was asked: a drive whose reply came after its wait (a later request met it),
// the silent addresses asked shortly before a garbled frame (any of them may be a late reply
// meeting a later request: a drive slower than the wait, a busy machine), and an address that
// answered but whose identification read then got no reply. None is asked more than `limit`
// times for each reason (docs/communication.md, "Scans").
class ScanReasks
{
public:
    explicit ScanReasks(int limit)
        : m_limit(limit)
    {
    }

    // A new scan; a garbled frame makes suspect the silent addresses asked up to `windowMs`
    // before the address being asked.
    void clear(double windowMs);
    bool hasQueued() const { return !m_queue.isEmpty(); }
    // The next address to ask again; hasQueued() must hold.
    int takeNext() { return m_queue.takeFirst(); }

    // The pass through the range is done with `slave`, asked at `atMs` into the scan: a silent
    // one is suspect for a while; those asked long before are forgotten.
    void passed(int slave, bool silent, double atMs);
    // The suspects asked within the window before `atMs` (the address asked when a garbled
    // frame came), oldest first.
    QVector<int> suspects(double atMs) const;
    // `slave` is there but its reply came too late: asked again, unless it already waits for
    // that or was asked again `limit` times. Asked with a long wait, it is no longer suspect.
    void askLate(int slave);
    // `slave` answered before, but its identification got no reply: asked again next. The
    // attempt (1 .. limit), or 0 when it has had them all.
    int retryIdentification(int slave);

    // `slave` sent a whole frame of some kind (an exception, a late reply): it is there.
    void answered(int slave) { m_answered.insert(slave); }
    bool hasAnswered(int slave) const { return m_answered.contains(slave); }

private:
    // An address asked with a short wait and judged silent, and when it was asked.
    struct Asked
    {
        int slave;
        double atMs;
    };

    int m_limit;
    double m_windowMs = 0;
    QVector<Asked> m_suspects;
    QVector<int> m_queue;       // to be asked again, in this order
    QSet<int> m_answered;       // sent a whole frame of some kind
    QHash<int, int> m_lateAsks; // times each address was asked again for a late reply
    QHash<int, int> m_retries;  // times each address was asked again after it answered
};

} // namespace opentop
