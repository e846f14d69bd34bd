// A drive's late reply to a request the line's previous user gave up on (issue 28): the next
// program checks every reply from that drive until the late-reply window is over, not only
// its first exchange. LateReplyJournal carries who and until when from one program to the
// next.
#include "transport/LateReplyJournal.h"
#include "tests/transport/TransportTestSupport.h"
#include "transport/RtuBackend.h"
#include "transport/RtuFrame.h"

#include <QDateTime>
#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <memory>

using namespace opentop;
using namespace opentop::test;

TEST(LateReplyJournalTest, EntriesGoFromOneProgramToTheNextOnce)
{
    QTemporaryDir dir;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const LateReplyJournal journal(QStringLiteral("/dev/ttyUSB0"), dir.path());
    journal.write({{3, now + 2000, 0x04, 5}, {7, now - 5}, {9, now + 900}});
    ASSERT_TRUE(QFile::exists(journal.path()));
    const QVector<LateReplyJournal::Entry> taken = journal.take(now);
    ASSERT_EQ(taken.size(), 2) << "an entry already over is dropped";
    EXPECT_EQ(taken[0].slave, 3);
    EXPECT_EQ(taken[0].untilMs, now + 2000);
    EXPECT_EQ(taken[0].function, 0x04) << "the shape of the request left unanswered";
    EXPECT_EQ(taken[0].count, 5);
    EXPECT_EQ(taken[1].slave, 9);
    EXPECT_EQ(taken[1].function, 0) << "a suspect without a request left unanswered";
    EXPECT_FALSE(QFile::exists(journal.path())) << "taken once";
    EXPECT_TRUE(journal.take(now).isEmpty());
    // Another device's journal is another file.
    journal.write({{3, now + 2000}});
    EXPECT_TRUE(LateReplyJournal(QStringLiteral("/dev/ttyUSB1"), dir.path()).take(now).isEmpty());
    // Nothing to leave: no file.
    journal.write({});
    EXPECT_FALSE(QFile::exists(journal.path()));
}

TEST(LateReplyJournalTest, AFileThatIsNotAJournalGivesNothing)
{
    QTemporaryDir dir;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const LateReplyJournal journal(QStringLiteral("/dev/ttyUSB0"), dir.path());
    QFile file(journal.path());
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    const QByteArray soon = QByteArray::number(now + 1000);
    file.write("0 99999999999999 3 1\n300 " + soon + " 3 1\nx y\n\n" + "5 " +
               QByteArray::number(now + 3600 * 1000) + " 3 1\n" + "6 " + soon + "\n" + "7 " + soon +
               " 200 1\n" + "8 " + soon + " 3 60000\n" + "10 " + soon + " 0 4\n" + "9 " +
               QByteArray::number(now + 500) + " 3 2\n");
    file.close();
    const QVector<LateReplyJournal::Entry> taken = journal.take(now);
    ASSERT_EQ(taken.size(), 1) << "no broadcast, no number above 247, nothing an hour away, "
                                  "no line without a shape, no function above 127, no count "
                                  "above 2000, no count without a function";
    EXPECT_EQ(taken[0].slave, 9);
    EXPECT_EQ(taken[0].function, 3);
    EXPECT_EQ(taken[0].count, 2);
}

namespace {

ModbusRequest readOf(quint16 address)
{
    return ModbusRequest::readHolding(1, address, 1);
}

std::unique_ptr<RtuBackend> openOn(const PtyDevice& device)
{
    ConnectionSettings s;
    s.port = device.path();
    s.baud = 19200;
    s.parity = 'N';
    auto backend = std::make_unique<RtuBackend>(s);
    QString error;
    EXPECT_TRUE(backend->open(&error)) << error.toStdString();
    return backend;
}

} // namespace

TEST(LateReplyJournalTest, TheNextProgramChecksEveryReplyOfADriveTheLastOneGaveUpOn)
{
    // (The test process has a journal folder of its own: PrivateUserDirs.)
    // The first program's read of 0x0311 gets no reply in time (the drive answers it late,
    // while the next program reads 0x0401: 1111 comes first, then 0x0401's own 2222).
    std::atomic<bool> late{false};
    PtyDevice device;
    device.start([&late](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        Answer a;
        if (r.address == 0x0311)
            return a; // silent: the reply comes later
        if (r.address == 0x0401 && !late.exchange(true)) {
            a.bytes = RtuFrame::encodeReadReply(1, 0x03, {1111});
            a.second = RtuFrame::encodeReadReply(1, 0x03, {2222});
            a.secondDelayMs = 5;
            return a;
        }
        a.bytes = RtuFrame::encodeReadReply(1, 0x03, {quint16(r.address)});
        return a;
    });
    {
        auto first = openOn(device);
        EXPECT_EQ(first->transact(readOf(0x0311), 100).error, ModbusError::Timeout);
    } // closed: the program exits
    auto next = openOn(device);
    // Its first exchange with the drive is clean; before issue 28 that cleared the drive.
    const ModbusResult clean = next->transact(readOf(0x0100), 300);
    ASSERT_EQ(clean.error, ModbusError::Ok) << clean.errorText().toStdString();
    const ModbusResult r = next->transact(readOf(0x0401), 300);
    EXPECT_FALSE(r.registers.contains(1111)) << "a late reply taken for 0x0401's answer";
    EXPECT_NE(r.error, ModbusError::Ok) << "two replies came: the one taken may be late";
    const ModbusResult again = next->transact(readOf(0x0401), 300);
    ASSERT_EQ(again.error, ModbusError::Ok) << again.errorText().toStdString();
    EXPECT_EQ(again.registers, QVector<quint16>({0x0401}));
}

// Issue 28 follow-up: only the shape the previous program left unanswered is read twice. A late
// reply of another function or length fails the frame's checks; reading every block of the
// drive twice for seconds halved a monitor's rate after a scan (CI, ScanWhileMonitoringE2e).
TEST(LateReplyJournalTest, TheNextProgramReadsTwiceOnlyTheShapeTheLastOneLeftUnanswered)
{
    std::atomic<int> requests{0};
    PtyDevice device;
    device.start([&requests](const QByteArray& request) {
        ModbusRequest r;
        RtuFrame::decodeRequest(request, &r);
        ++requests;
        Answer a;
        if (r.address == 0x0311)
            return a; // silent
        QVector<quint16> values;
        for (int i = 0; i < r.count; ++i)
            values << quint16(r.address + i);
        a.bytes = RtuFrame::encodeReadReply(1, 0x03, values);
        return a;
    });
    {
        auto first = openOn(device);
        EXPECT_EQ(first->transact(readOf(0x0311), 100).error, ModbusError::Timeout);
    }
    auto next = openOn(device);
    requests = 0;
    const ModbusResult other = next->transact(ModbusRequest::readHolding(1, 0x0100, 2), 300);
    ASSERT_EQ(other.error, ModbusError::Ok) << other.errorText().toStdString();
    EXPECT_EQ(requests.load(), 1) << "a read of two registers cannot take a one-register reply";
    requests = 0;
    const ModbusResult same = next->transact(readOf(0x0401), 300);
    ASSERT_EQ(same.error, ModbusError::Ok) << same.errorText().toStdString();
    EXPECT_EQ(same.registers, QVector<quint16>({0x0401}));
    EXPECT_EQ(requests.load(), 2) << "the shape left unanswered is read twice";
}
