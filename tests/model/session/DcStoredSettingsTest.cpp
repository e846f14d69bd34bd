// The DC controller's settings that only a one-frame write stores (errata DC-18): baud rate and
// parity as the 15-register 0x10 write from 0x0080, AI1/AI2 as the 5-register write from 0x0050,
// each reading the block first; they survive a simulated power cycle. Also the recommended
// range of the PID coefficients and the serial lock's warning, through the session.
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "model/session/SerialLock.h"
#include "sim/SimDevice.h"
#include "tests/model/DriveSimFixture.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

struct Frame
{
    quint16 address = 0;
    quint16 count = 0;
    QVector<quint16> values;
};

class DcStoredSettingsTest : public test::DriveSimFixture
{
protected:
    void SetUp() override { startBus(QStringLiteral("dcpid@7"), 0, 100, 1); }

    DeviceSession::Outcome write(const char* name, const char* text)
    {
        return await<DeviceSession::Outcome>([&](DeviceSession::Done done) {
            session(7)->write(QString::fromLatin1(name), QString::fromLatin1(text), {}, done);
        });
    }

    DeviceSession::Outcome read(const char* name)
    {
        return await<DeviceSession::Outcome>(
            [&](DeviceSession::Done done) { session(7)->read(QString::fromLatin1(name), done); });
    }

    // The 0x10 requests sent since the log was last cleared.
    QVector<Frame> writeMultipleFrames() const
    {
        QVector<Frame> frames;
        for (const TrafficEntry& e : log.entries()) {
            if (e.direction != TrafficEntry::Direction::Tx || e.function != 0x10)
                continue;
            const QByteArray& b = e.bytes;
            auto word = [&b](int at) {
                return quint16((quint8(b.at(at)) << 8) | quint8(b.at(at + 1)));
            };
            Frame f;
            f.address = word(2);
            f.count = word(4);
            for (int i = 0; i < f.count; ++i)
                f.values << word(7 + 2 * i);
            frames << f;
        }
        return frames;
    }

    void powerCycle() { control(7, {QStringLiteral("power-cycle")}); }
};

} // namespace

TEST_F(DcStoredSettingsTest, BaudRateAndParityGoAsTheFifteenRegisterWriteAndSurviveAPowerCycle)
{
    // A configuration change in effect but not stored: the block write must keep it.
    ASSERT_TRUE(write("config.rated_current", "3.25").ok);
    log.clear();
    const DeviceSession::Outcome baud = write("config.baud", "19200");
    ASSERT_TRUE(baud.ok) << qPrintable(baud.error);
    EXPECT_TRUE(baud.verified);
    const DeviceSession::Outcome parity = write("config.parity", "Odd, 1 stop bit");
    ASSERT_TRUE(parity.ok) << qPrintable(parity.error);
    EXPECT_TRUE(parity.verified);

    const QVector<Frame> frames = writeMultipleFrames();
    ASSERT_EQ(frames.size(), 2);
    for (const Frame& f : frames) {
        EXPECT_EQ(f.address, 0x0080);
        EXPECT_EQ(f.count, 15);
        EXPECT_EQ(f.values.at(0x0086 - 0x0080), 325); // the rated current as it was in effect
    }
    EXPECT_EQ(frames.at(0).values.mid(0x008A - 0x0080, 2), (QVector<quint16>{0x0000, 0x4B00}));
    EXPECT_EQ(frames.at(1).values.at(0x008C - 0x0080), 1);

    // The controller keeps talking at the old settings until it is switched off and on.
    SimDevice* device = bus->device(7);
    EXPECT_EQ(device->lineBaud(), 9600);
    EXPECT_EQ(device->lineParity(), 'E');
    powerCycle();
    EXPECT_EQ(device->lineBaud(), 19200);
    EXPECT_EQ(device->lineParity(), 'O');
    EXPECT_EQ(read("config.baud").value.raw, 19200);
    EXPECT_EQ(read("config.parity").value.raw, 1);
    EXPECT_DOUBLE_EQ(read("config.rated_current").value.number, 3.25); // stored with them
}

TEST_F(DcStoredSettingsTest, AnOrdinaryConfigurationWriteIsStillLostAtPowerOff)
{
    // The contrast that makes the test above mean something: a 06 write is temporary.
    const double before = read("config.stall_time").value.number;
    ASSERT_TRUE(write("config.stall_time", "2.5").ok);
    EXPECT_TRUE(writeMultipleFrames().isEmpty());
    powerCycle();
    EXPECT_DOUBLE_EQ(read("config.stall_time").value.number, before);
}

TEST_F(DcStoredSettingsTest, GpioSettingsGoAsTheFiveRegisterWriteAndSurviveAPowerCycle)
{
    ASSERT_TRUE(write("gpio.ai2_direction", "Output").ok);
    log.clear();
    const DeviceSession::Outcome level = write("gpio.ai2_level", "High");
    ASSERT_TRUE(level.ok) << qPrintable(level.error);
    EXPECT_TRUE(level.verified);
    const QVector<Frame> frames = writeMultipleFrames();
    ASSERT_EQ(frames.size(), 1);
    EXPECT_EQ(frames.first().address, 0x0050);
    EXPECT_EQ(frames.first().count, 5);
    // AI1 as it was, AI2 an output (kept from the first write), AI2 high, then the store flag.
    EXPECT_EQ(frames.first().values, (QVector<quint16>{0, 1, 0, 1, 1}));
    powerCycle();
    EXPECT_EQ(read("gpio.ai2_direction").value.raw, 1);
    EXPECT_EQ(read("gpio.ai2_level").value.raw, 1);
}

TEST_F(DcStoredSettingsTest, PidAboveTheRecommendationIsWrittenWithAWarning)
{
    DeviceSession::Outcome o = write("pid.p", "2.5");
    ASSERT_TRUE(o.ok) << qPrintable(o.error);
    EXPECT_TRUE(o.verified);
    EXPECT_DOUBLE_EQ(o.value.number, 2.5);
    EXPECT_TRUE(o.warning.contains(QStringLiteral("recommended range 0.0000–1.0000")))
        << qPrintable(o.warning);
    o = write("pid.p", "0.5");
    ASSERT_TRUE(o.ok) << qPrintable(o.error);
    EXPECT_TRUE(o.warning.isEmpty()) << qPrintable(o.warning);
    const int sent = framesSent();
    o = write("pid.d", "150");
    EXPECT_FALSE(o.ok);
    EXPECT_FALSE(o.sent);
    EXPECT_EQ(framesSent(), sent);
    EXPECT_TRUE(o.error.contains(QStringLiteral("0.0000–100.0000"))) << qPrintable(o.error);
}

TEST(SerialLock, WarnsOnlyWhenTheLockIsSetAndSaysHowToUndoIt)
{
    const Profile& dc = *ProfileRegistry::builtIn().family(QStringLiteral("dcpid"));
    const ParameterMeta& lock = *dc.parameter(QStringLiteral("config.serial_lock"));
    const QString text = SerialLock::warning(dc, lock, 1);
    EXPECT_TRUE(SerialLock::locks(dc, lock, 1));
    EXPECT_TRUE(text.startsWith(QStringLiteral("config.serial_lock = Disabled (1) prohibits")))
        << qPrintable(text);
    for (const char* part : {"switch the drive off and on", "potentiometer/analog control",
                             "9600 bit/s, 8E1, address 1", "config.serial_lock = Allowed (0)"})
        EXPECT_TRUE(text.contains(QString::fromUtf8(part))) << part << "\n" << qPrintable(text);
    EXPECT_FALSE(SerialLock::locks(dc, lock, 0));
    EXPECT_TRUE(SerialLock::warning(dc, lock, 0).isEmpty());
    EXPECT_TRUE(
        SerialLock::warning(dc, *dc.parameter(QStringLiteral("config.parity")), 1).isEmpty());
    const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    for (const ParameterMeta& p : dbu.parameters)
        EXPECT_FALSE(SerialLock::locks(dbu, p, 1)) << qPrintable(p.name);
}
