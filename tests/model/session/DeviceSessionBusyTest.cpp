// A DBU busy with internal processing refuses a write with exception 04 and leaves E3h in its
// communication error register: nothing was executed, so a setting is sent again (found by
// the fault matrix, issue 11: 1 % busy replies made every other 32-drive restore give up).
// Commands are not sent again on their own.
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "transport/MockBackend.h"
#include "transport/ModbusClient.h"
#include "transport/RtuFrame.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <atomic>
#include <gtest/gtest.h>
#include <memory>

using namespace opentop;

namespace {

// A drive that answers the first `busyWrites` writes with exception 04 (E3h Busy in 0x007B)
// and every read with the register's address (0x007B: its error code).
struct BusyDrive
{
    explicit BusyDrive(int busyWrites)
    {
        auto writes = std::make_shared<std::atomic<int>>(0);
        auto sent = sentWrites;
        auto backend =
            std::make_unique<MockBackend>([writes, sent, busyWrites](const QByteArray& adu) {
                ModbusRequest r;
                RtuFrame::decodeRequest(adu, &r);
                if (r.isWrite()) {
                    ++*sent;
                    if (++*writes <= busyWrites)
                        return RtuFrame::encodeException(r.slave, r.function, 0x04);
                    return RtuFrame::encodeWriteSingleReply(r.slave, r.address, r.values.value(0));
                }
                QVector<quint16> values;
                for (int i = 0; i < r.count; ++i)
                    values << (r.address + i == 0x007B ? quint16(0xE3) : quint16(0));
                return RtuFrame::encodeReadReply(r.slave, r.function, values);
            });
        ConnectionSettings settings;
        settings.timeoutMs = 100;
        settings.retries = 0;
        client = std::make_unique<ModbusClient>(std::move(backend), settings);
        EXPECT_EQ(client->openBlocking(), QString());
    }

    DeviceSession::Outcome write(const QString& name, const QString& value)
    {
        const Profile* dbu = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
        DeviceSession session(client.get(), *dbu, 1, QStringLiteral("dbu200"));
        DeviceSession::Outcome result;
        bool finished = false;
        DeviceSession::WriteOptions options;
        options.verify = false;
        options.explicitCommand = true;
        session.write(name, value, options, [&](const DeviceSession::Outcome& o) {
            result = o;
            finished = true;
        });
        QElapsedTimer timer;
        timer.start();
        while (!finished && timer.elapsed() < 5000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        EXPECT_TRUE(finished);
        return result;
    }

    std::shared_ptr<std::atomic<int>> sentWrites = std::make_shared<std::atomic<int>>(0);
    std::unique_ptr<ModbusClient> client;
};

} // namespace

TEST(DeviceSessionBusy, ASettingRefusedAsBusyIsSentAgain)
{
    BusyDrive drive(2);
    const DeviceSession::Outcome o =
        drive.write(QStringLiteral("spno2.accel"), QStringLiteral("2"));
    EXPECT_TRUE(o.ok) << o.error.toStdString();
    EXPECT_EQ(drive.sentWrites->load(), 3);
}

TEST(DeviceSessionBusy, BusyForEverFailsAfterThreeMoreAndSaysWhy)
{
    BusyDrive drive(100);
    const DeviceSession::Outcome o =
        drive.write(QStringLiteral("spno2.accel"), QStringLiteral("2"));
    EXPECT_FALSE(o.ok);
    EXPECT_EQ(drive.sentWrites->load(), 4);
    EXPECT_TRUE(o.error.contains(QStringLiteral("E3h"))) << o.error.toStdString();
}

TEST(DeviceSessionBusy, ACommandIsNotSentAgain)
{
    BusyDrive drive(100);
    const DeviceSession::Outcome o =
        drive.write(QStringLiteral("cmd.alarm_reset"), QStringLiteral("Reset"));
    EXPECT_FALSE(o.ok);
    EXPECT_EQ(drive.sentWrites->load(), 1) << o.error.toStdString();
}
