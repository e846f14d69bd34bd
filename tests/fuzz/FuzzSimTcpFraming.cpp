// libFuzzer harness: the simulator's Modbus TCP framing (TcpFrameReader, which TcpSimServer reads
// each client's stream with). Byte 0 seeds where the stream is cut into the pieces a socket
// delivers; the rest is the stream. The frames must not depend on the cuts, each must be a
// well-formed MBAP frame, together they must be the start of the stream, and a reply built on a
// frame's header must read back as a frame with the same header and contents.
#include "sim/TcpFrameReader.h"
#include <QByteArray>
#include <QVector>
#include <cstddef>
#include <cstdint>

using opentop::TcpFrameReader;

namespace {

struct Reading
{
    QVector<TcpFrameReader::Frame> frames;
    TcpFrameReader::Status last = TcpFrameReader::Status::NeedMore;
};

// Frames read from `stream` delivered in pieces whose sizes come from `cuts` (0: in one piece).
Reading readInPieces(const QByteArray& stream, uint8_t cuts)
{
    Reading reading;
    TcpFrameReader reader;
    uint32_t state = cuts * 2654435761u + 1;
    qsizetype at = 0;
    while (at < stream.size() && reading.last != TcpFrameReader::Status::Invalid) {
        state = state * 1103515245u + 12345u;
        const qsizetype piece = cuts == 0 ? stream.size() : 1 + qsizetype((state >> 16) % 23);
        reader.append(stream.mid(at, piece));
        at += piece;
        TcpFrameReader::Frame frame;
        while ((reading.last = reader.next(&frame)) == TcpFrameReader::Status::Ready)
            reading.frames << frame;
    }
    return reading;
}

void checkFrame(const TcpFrameReader::Frame& frame)
{
    if (frame.header.size() != 6 || frame.header.at(2) != 0 || frame.header.at(3) != 0)
        __builtin_trap();
    const int length = (quint8(frame.header.at(4)) << 8) | quint8(frame.header.at(5));
    if (length != frame.unitAndPdu.size() || length < TcpFrameReader::kMinLength ||
        length > TcpFrameReader::kMaxLength)
        __builtin_trap();
    // the simulator's reply echoes the header; read back, it is the same frame
    TcpFrameReader back;
    back.append(TcpFrameReader::replyFrame(frame.header, frame.unitAndPdu));
    TcpFrameReader::Frame again;
    if (back.next(&again) != TcpFrameReader::Status::Ready || again.header != frame.header ||
        again.unitAndPdu != frame.unitAndPdu || back.buffered() != 0)
        __builtin_trap();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size < 1)
        return 0;
    const QByteArray stream(reinterpret_cast<const char*>(data + 1),
                            static_cast<qsizetype>(size - 1));
    const Reading whole = readInPieces(stream, 0);
    const Reading cut = readInPieces(stream, data[0] == 0 ? 1 : data[0]);
    if (whole.frames.size() != cut.frames.size() || whole.last != cut.last)
        __builtin_trap();
    QByteArray consumed;
    for (int i = 0; i < whole.frames.size(); ++i) {
        const TcpFrameReader::Frame& frame = whole.frames.at(i);
        if (frame.header != cut.frames.at(i).header ||
            frame.unitAndPdu != cut.frames.at(i).unitAndPdu)
            __builtin_trap();
        checkFrame(frame);
        consumed += frame.header + frame.unitAndPdu;
    }
    if (!stream.startsWith(consumed))
        __builtin_trap();
    return 0;
}
