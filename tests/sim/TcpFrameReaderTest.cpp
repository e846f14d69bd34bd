// The simulator's Modbus TCP framing without a socket (TcpFrameReader, what TcpSimServer reads
// each client with): frames whole whatever pieces the bytes come in, a stream that is not
// Modbus TCP refused for good, and the reply echoing the request's header.
#include "tests/sim/SimTestSupport.h"

#include "sim/TcpFrameReader.h"

using namespace opentop;
using namespace opentop::test;

namespace {

using Status = TcpFrameReader::Status;

} // namespace

TEST(TcpFrameReader, FramesAStreamWhateverPiecesItComesIn)
{
    const QByteArray read = hexBytes("00 05 00 00 00 06 01 03 CA 03 00 01");
    const QByteArray write = hexBytes("00 06 00 00 00 09 07 10 00 10 00 01 02 00 2A");
    const QByteArray stream = read + write + hexBytes("00 07 00"); // and the start of a third
    for (int piece = 1; piece <= stream.size(); ++piece) {
        TcpFrameReader reader;
        QVector<TcpFrameReader::Frame> frames;
        Status last = Status::NeedMore;
        for (int at = 0; at < stream.size(); at += piece) {
            reader.append(stream.mid(at, piece));
            TcpFrameReader::Frame frame;
            while ((last = reader.next(&frame)) == Status::Ready)
                frames << frame;
        }
        ASSERT_EQ(frames.size(), 2) << "pieces of " << piece;
        EXPECT_EQ(last, Status::NeedMore);
        EXPECT_EQ(frames.at(0).header, hexBytes("00 05 00 00 00 06"));
        EXPECT_EQ(frames.at(0).unitAndPdu, hexBytes("01 03 CA 03 00 01"));
        EXPECT_EQ(frames.at(1).header, hexBytes("00 06 00 00 00 09"));
        EXPECT_EQ(frames.at(1).unitAndPdu, hexBytes("07 10 00 10 00 01 02 00 2A"));
        EXPECT_EQ(reader.buffered(), 3);
    }
}

TEST(TcpFrameReader, AStreamThatIsNotModbusTcpIsRefusedForGood)
{
    TcpFrameReader::Frame frame;
    TcpFrameReader otherProtocol;
    otherProtocol.append(hexBytes("00 01 00 01 00 06 01 03 CA 03 00 01"));
    EXPECT_EQ(otherProtocol.next(&frame), Status::Invalid);
    EXPECT_EQ(otherProtocol.buffered(), 0);
    // nothing after it is read: there is no telling where a next frame would start
    otherProtocol.append(hexBytes("00 05 00 00 00 06 01 03 CA 03 00 01"));
    EXPECT_EQ(otherProtocol.next(&frame), Status::Invalid);
    EXPECT_EQ(otherProtocol.buffered(), 0);

    // the length counts the unit id and the PDU: 2 to 254
    for (const char* header :
         {"00 01 00 00 00 01 01", "00 01 00 00 00 FF 01", "00 01 00 00 00 00 01"}) {
        TcpFrameReader reader;
        reader.append(hexBytes(header));
        EXPECT_EQ(reader.next(&frame), Status::Invalid) << header;
    }
    TcpFrameReader longest;
    longest.append(hexBytes("00 01 00 00 00 FE") + QByteArray(254, '\x01'));
    ASSERT_EQ(longest.next(&frame), Status::Ready);
    EXPECT_EQ(frame.unitAndPdu.size(), 254);
    // a header not yet whole is not judged
    TcpFrameReader partial;
    partial.append(hexBytes("00 01 00 01 00"));
    EXPECT_EQ(partial.next(&frame), Status::NeedMore);
}

TEST(TcpFrameReader, TheReplyEchoesTheRequestsTransactionWithItsOwnLength)
{
    EXPECT_EQ(TcpFrameReader::replyFrame(hexBytes("12 34 00 00 00 06"), hexBytes("01 03 02 03 E8")),
              hexBytes("12 34 00 00 00 05 01 03 02 03 E8"));
}
