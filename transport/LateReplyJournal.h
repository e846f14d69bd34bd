#pragma once

#include <QString>
#include <QVector>

namespace opentop {

// What a program that gives a serial line up leaves for the next one (issue 28): the drives
// that may still answer a request it gave up on, and until when. RTU has no transaction ids,
// so such a late reply reaches the next program's requests of the same shape: a compare run
// right after a restore took a drive's reply 450 ms late, from the restore, for a block of its
// own. With the journal the next program checks every reply from those drives until then
// (LateReplyWatch), not only the first. One small file per device in a directory of the user's
// own, written when the port is closed and taken (read, then removed) when it is opened. A
// program killed first leaves none; LateReplyWatch::opened() then still checks each drive's
// first exchange. Times are wall-clock ms since the epoch: the two programs share no clock.
// A line per entry: "slave until function count".
class LateReplyJournal
{
public:
    struct Entry
    {
        quint8 slave = 0;
        qint64 untilMs = 0;
        quint8 function = 0; // with `count`: the shape of a request left unanswered; 0: none
        int count = 0;
    };

    // `device`: the port's canonical path (/dev/ttyUSB0, /dev/pts/3).
    explicit LateReplyJournal(const QString& device, const QString& directory = defaultDirectory());

    // Replaces the journal; no entries removes it. Failures are logged, never fatal: the
    // journal only narrows what the next program must check.
    void write(const QVector<Entry>& entries) const;
    // The entries not yet over at `nowMs`, and the file removed.
    QVector<Entry> take(qint64 nowMs) const;
    QString path() const { return m_path; }

    // OPENTOP_LATE_JOURNAL_DIR, else opentop-late-UID in the temporary directory.
    static QString defaultDirectory();

private:
    QString m_path;
};

} // namespace opentop
