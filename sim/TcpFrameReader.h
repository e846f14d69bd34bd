#pragma once

#include <QByteArray>

namespace opentop {

// Modbus TCP framing (MBAP) of one client's byte stream, apart from the socket so that it can be
// tested and fuzzed (tests/fuzz/FuzzSimTcpFraming.cpp): bytes go in as the socket delivers them,
// in pieces of any size, and whole frames come out in order.
class TcpFrameReader
{
public:
    static constexpr int kHeaderBytes = 7; // transaction(2) protocol(2) length(2) unit(1)
    static constexpr int kMinLength = 2;   // the length field counts the unit id and the PDU
    static constexpr int kMaxLength = 254; // a unit id and the longest PDU (253 bytes)

    struct Frame
    {
        QByteArray header;     // transaction, protocol and length (6 bytes)
        QByteArray unitAndPdu; // the unit id and the PDU: an RTU frame without its CRC
    };
    enum class Status
    {
        NeedMore, // no whole frame yet
        Ready,    // *frame holds the next frame
        Invalid   // not Modbus TCP: the stream is dropped and stays refused
    };

    void append(const QByteArray& bytes);
    // The next whole frame. A protocol id other than 0 or a length outside 2–254 makes the rest
    // of the stream unreadable (there is no way to find the next frame): Invalid from then on.
    Status next(Frame* frame);
    qsizetype buffered() const { return m_buffer.size(); }

    // The reply to a request with `requestHeader`: its transaction and protocol id, and the
    // length of `unitAndPdu`, which follows.
    static QByteArray replyFrame(const QByteArray& requestHeader, const QByteArray& unitAndPdu);

private:
    QByteArray m_buffer;
    bool m_invalid = false;
};

} // namespace opentop
