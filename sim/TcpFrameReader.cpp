#include "sim/TcpFrameReader.h"

namespace opentop {

namespace {

quint16 word(const QByteArray& bytes, int at)
{
    return quint16((quint8(bytes.at(at)) << 8) | quint8(bytes.at(at + 1)));
}

} // namespace

void TcpFrameReader::append(const QByteArray& bytes)
{
    if (!m_invalid)
        m_buffer.append(bytes);
}

TcpFrameReader::Status TcpFrameReader::next(Frame* frame)
{
    if (m_invalid)
        return Status::Invalid;
    if (m_buffer.size() < kHeaderBytes)
        return Status::NeedMore;
    const int length = word(m_buffer, 4);
    if (word(m_buffer, 2) != 0 || length < kMinLength || length > kMaxLength) {
        m_invalid = true;
        m_buffer.clear();
        return Status::Invalid;
    }
    if (m_buffer.size() < 6 + length)
        return Status::NeedMore;
    frame->header = m_buffer.left(6);
    frame->unitAndPdu = m_buffer.mid(6, length);
    m_buffer.remove(0, 6 + length);
    return Status::Ready;
}

QByteArray TcpFrameReader::replyFrame(const QByteArray& requestHeader, const QByteArray& unitAndPdu)
{
    QByteArray frame = requestHeader.left(4);
    frame.append(char((unitAndPdu.size() >> 8) & 0xFF));
    frame.append(char(unitAndPdu.size() & 0xFF));
    frame.append(unitAndPdu);
    return frame;
}

} // namespace opentop
