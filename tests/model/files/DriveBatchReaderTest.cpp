// DriveBatchReader, the one "read these drives" of backup, compare and recipe creation: every
// drive read in order with its result; a drive not on the bus says why and the others are still
// read; a cancel, or the first failure with stopAtFailure, reports the rest as not read; a
// preparation that refuses a drive skips its read.
#include "model/files/DriveBatchReader.h"
#include "tests/model/files/BackupTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class DriveBatchReaderTest : public SimBusFixture
{
protected:
    DriveBatchReader::Sessions sessions()
    {
        return [this](int slave, QString* error) -> DeviceSession* {
            if (slave == 1 || slave == 150 || slave == 7)
                return session(slave);
            *error = QStringLiteral("machine number %1 did not answer").arg(slave);
            return nullptr;
        };
    }

    QVector<DriveBatchReader::Drive> read(DriveBatchReader& reader, const QVector<int>& slaves,
                                          const DriveBatchReader::Options& options = {})
    {
        return waitFor<QVector<DriveBatchReader::Drive>>(
            [&](auto done) { reader.start(slaves, options, done); });
    }
};

} // namespace

TEST_F(DriveBatchReaderTest, EveryDriveIsReadAndOneMissingIsNamedWithoutStoppingTheOthers)
{
    DriveBatchReader reader(sessions());
    QVector<int> started;
    QObject::connect(&reader, &DriveBatchReader::driveStarted,
                     [&started](int slave, int, int) { started << slave; });
    const QVector<DriveBatchReader::Drive> drives = read(reader, {1, 33, 150, 7});
    ASSERT_EQ(drives.size(), 4);
    EXPECT_EQ(started, (QVector<int>{1, 33, 150, 7}));
    EXPECT_TRUE(drives[0].ok());
    EXPECT_EQ(drives[0].read.device.slave, 1);
    EXPECT_GT(drives[0].read.parameters, 10);
    EXPECT_FALSE(drives[1].ok());
    EXPECT_TRUE(drives[1].attempted);
    EXPECT_EQ(drives[1].problems(), QStringList{QStringLiteral("machine number 33 did not answer")});
    EXPECT_TRUE(drives[2].ok());
    EXPECT_EQ(drives[2].read.device.variant, QStringLiteral("dbu400"));
    EXPECT_TRUE(drives[3].ok());
    EXPECT_EQ(drives[3].read.device.family, QStringLiteral("dcpid"));
}

TEST_F(DriveBatchReaderTest, TheFirstFailureOrACancelLeavesTheRestNotReadAndSaysSo)
{
    DriveBatchReader reader(sessions());
    DriveBatchReader::Options stop;
    stop.stopAtFailure = true;
    QVector<DriveBatchReader::Drive> drives = read(reader, {33, 1, 7}, stop);
    ASSERT_EQ(drives.size(), 3);
    EXPECT_TRUE(drives[0].attempted);
    EXPECT_FALSE(drives[1].attempted);
    EXPECT_FALSE(drives[2].attempted);
    EXPECT_EQ(drives[2].problems(), QStringList{QStringLiteral("machine number 7: not read")});

    // Cancelled while the first is read: it finishes, the others are not read.
    QObject::connect(&reader, &DriveBatchReader::driveStarted, &reader,
                     [&reader](int, int index, int) {
                         if (index == 0)
                             reader.cancel();
                     });
    drives = read(reader, {1, 150, 7});
    ASSERT_EQ(drives.size(), 3);
    EXPECT_TRUE(drives[0].ok());
    EXPECT_FALSE(drives[1].attempted);
    EXPECT_FALSE(drives[2].attempted);
}

TEST_F(DriveBatchReaderTest, APreparationThatRefusesADriveSkipsItsRead)
{
    DriveBatchReader reader(sessions());
    DriveBatchReader::Options options;
    QVector<int> prepared;
    options.prepare = [&prepared](DeviceSession* session,
                                  std::function<void(const QString&)> go) {
        prepared << session->slave();
        go(session->slave() == 150 ? QStringLiteral("variant not known") : QString());
    };
    const QVector<DriveBatchReader::Drive> drives = read(reader, {1, 150}, options);
    EXPECT_EQ(prepared, (QVector<int>{1, 150}));
    ASSERT_EQ(drives.size(), 2);
    EXPECT_TRUE(drives[0].ok());
    EXPECT_FALSE(drives[1].ok());
    EXPECT_EQ(drives[1].error, QStringLiteral("variant not known"));
    EXPECT_EQ(drives[1].read.requests, 0); // nothing was read from it
}
