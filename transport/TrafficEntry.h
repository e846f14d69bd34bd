#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QString>

namespace opentop {

// One frame on the wire, as the traffic log keeps it.
struct TrafficEntry
{
    enum class Direction
    {
        Tx,
        Rx,
        Event
    };

    // A frame that answered nothing asked now: bytes waiting before a request, bytes drained
    // after an error, a reply sooner than the wire allows. Counted as late, not as replies.
    enum class Kind
    {
        Frame,
        Late
    };

    quint64 sequence = 0;
    QDateTime time;
    Direction direction = Direction::Tx;
    quint8 slave = 0;
    quint8 function = 0;
    QByteArray bytes;       // the whole ADU as sent or received
    QString summary;        // decoded meaning, e.g. "read 04 0x0109 x1" or "= 1500"
    QString error;          // empty when none
    double responseMs = -1; // Rx only: time from request to reply
    Kind kind = Kind::Frame;

    QString directionText() const;
    QString toLine() const; // one human line, as --trace prints it
};

} // namespace opentop
