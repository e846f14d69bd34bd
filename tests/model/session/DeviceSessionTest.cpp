#include "model/session/DeviceSession.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceIdentifier.h"
#include "sim/SimBackend.h"
#include "sim/SimBus.h"
#include "sim/SimDevice.h"
#include "tests/model/DriveSimFixture.h"
#include "transport/ModbusClient.h"
#include "transport/TrafficLog.h"

#include <QEventLoop>
#include <QTimer>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// A DBU200 at 1 and a DBU400 at 150 and a DC controller at 7, in process.
class DeviceSessionTest : public test::DriveSimFixture
{
protected:
    void SetUp() override { startBus(QStringLiteral("dbu200@1,dbu400@150,dcpid@7"), 0, 100, 1); }

    DeviceSession::Outcome wait(const std::function<void(DeviceSession::Done)>& start)
    {
        return await<DeviceSession::Outcome>(start, 5000);
    }

    const Profile& dbu() const { return *ProfileRegistry::builtIn().family(QStringLiteral("dbu")); }
};

} // namespace

TEST_F(DeviceSessionTest, WritesByNameAndVerifiesByReadingBack)
{
    DeviceSession session(client.get(), dbu(), 1, QStringLiteral("dbu200"));
    const auto o = wait([&](auto done) {
        session.write(QStringLiteral("spno2.accel"), QStringLiteral("2.5"), {}, done);
    });
    EXPECT_TRUE(o.ok) << qPrintable(o.error);
    EXPECT_TRUE(o.verified);
    EXPECT_DOUBLE_EQ(o.value.number, 2.5);
    // The simulated drive holds the new raw value (25 at 0.1 s).
    const auto held = bus->control(1, {QStringLiteral("get"), QStringLiteral("0x1303")});
    EXPECT_TRUE(held.text.contains(QStringLiteral("25"))) << qPrintable(held.text);
}

TEST_F(DeviceSessionTest, InvalidValueIsRefusedAndNothingIsSent)
{
    DeviceSession session(client.get(), dbu(), 150, QStringLiteral("dbu400"));
    const int before = framesSent();
    const auto o = wait([&](auto done) {
        session.write(QStringLiteral("spno2.speed"), QStringLiteral("280"), {}, done);
    });
    EXPECT_FALSE(o.ok);
    EXPECT_FALSE(o.sent);
    EXPECT_TRUE(o.error.contains(QStringLiteral("0 or 300–3000 r/min"))) << qPrintable(o.error);
    EXPECT_EQ(framesSent(), before);
}

TEST_F(DeviceSessionTest, CommandsNeedAnExplicitRequest)
{
    DeviceSession session(client.get(), dbu(), 1, QStringLiteral("dbu200"));
    const int before = framesSent();
    const auto refused = wait([&](auto done) {
        session.write(QStringLiteral("run.start"), QStringLiteral("START"), {}, done);
    });
    EXPECT_FALSE(refused.ok);
    EXPECT_FALSE(refused.sent);
    EXPECT_EQ(framesSent(), before);
    // Asked explicitly, but the drive is in I/O priority: the drive refuses (exception 04) and
    // the communication error register tells why.
    DeviceSession::WriteOptions explicitly;
    explicitly.explicitCommand = true;
    const auto o = wait([&](auto done) {
        session.write(QStringLiteral("run.start"), QStringLiteral("START"), explicitly, done);
    });
    EXPECT_FALSE(o.ok);
    EXPECT_TRUE(o.sent);
    EXPECT_TRUE(o.error.contains(QStringLiteral("04"))) << qPrintable(o.error);
    EXPECT_TRUE(o.deviceError.startsWith(QStringLiteral("E2h"))) << qPrintable(o.deviceError);
}

TEST_F(DeviceSessionTest, DependentEnumerationReadsItsControllingParameterFirst)
{
    DeviceSession session(client.get(), dbu(), 1, QStringLiteral("dbu200"));
    EXPECT_FALSE(session.hasCached(QStringLiteral("core.control_mode")));
    // Mode2 is the default: RUN/STOP (a Mode1 function) is refused without sending a write.
    const auto o = wait([&](auto done) {
        session.write(QStringLiteral("io.x0"), QStringLiteral("RUN/STOP"), {}, done);
    });
    EXPECT_FALSE(o.ok);
    EXPECT_TRUE(session.hasCached(QStringLiteral("core.control_mode")));
    EXPECT_TRUE(o.error.contains(QStringLiteral("CW/STOP"))) << qPrintable(o.error);
    const auto ok = wait(
        [&](auto done) { session.write(QStringLiteral("io.x0"), QStringLiteral("M2"), {}, done); });
    EXPECT_TRUE(ok.ok) << qPrintable(ok.error);
    EXPECT_EQ(ok.value.registers, QVector<quint16>{0x17});
}

TEST_F(DeviceSessionTest, ReadsDecodeAndTimeoutsAreReported)
{
    DeviceSession dc(client.get(), *ProfileRegistry::builtIn().family(QStringLiteral("dcpid")), 7,
                     QString());
    const auto name = wait([&](auto done) { dc.read(QStringLiteral("info.device_name"), done); });
    EXPECT_TRUE(name.ok) << qPrintable(name.error);
    EXPECT_FALSE(name.value.text.isEmpty());
    DeviceSession absent(client.get(), dbu(), 99, QString());
    const auto o =
        wait([&](auto done) { absent.read(QStringLiteral("status.current_speed"), done); });
    EXPECT_FALSE(o.ok);
    EXPECT_TRUE(o.error.contains(QStringLiteral("timeout"), Qt::CaseInsensitive))
        << qPrintable(o.error);
}

TEST_F(DeviceSessionTest, IdentifierTellsFamiliesApart)
{
    DeviceIdentifier identifier(client.get(), ProfileRegistry::builtIn());
    QVector<DeviceInfo> found;
    QEventLoop loop;
    for (int slave : {1, 7, 150, 42}) {
        identifier.identify(slave, [&](const DeviceInfo& info) {
            found << info;
            if (found.size() == 4)
                loop.quit();
        });
    }
    QTimer::singleShot(5000, &loop, &QEventLoop::quit);
    loop.exec();
    ASSERT_EQ(found.size(), 4);
    std::sort(found.begin(), found.end(),
              [](const DeviceInfo& a, const DeviceInfo& b) { return a.slave < b.slave; });
    EXPECT_EQ(found[0].family, QStringLiteral("dbu"));
    EXPECT_EQ(found[0].state, DeviceInfo::State::Present);
    EXPECT_FALSE(found[0].firmware.isEmpty());
    EXPECT_EQ(found[1].family, QStringLiteral("dcpid"));
    EXPECT_EQ(found[2].state, DeviceInfo::State::Absent);
    EXPECT_EQ(found[3].slave, 150);
    EXPECT_EQ(found[3].family, QStringLiteral("dbu"));
    EXPECT_EQ(DeviceInfo::hexText(150), QStringLiteral("96h"));
    EXPECT_EQ(DeviceInfo::switchText(150), QStringLiteral("SW1=9 SW2=6"));
}

TEST_F(DeviceSessionTest, ReadManyUsesBlocksAndFallsBackWhereRefused)
{
    DeviceSession session(client.get(), dbu(), 1, QStringLiteral("dbu200"));
    QStringList names;
    for (const ParameterMeta& m : dbu().parameters) {
        if (m.backup)
            names << m.name;
    }
    DeviceSession::ReadManyOutcome result;
    QEventLoop loop;
    session.readMany(names, [&](const DeviceSession::ReadManyOutcome& o) {
        result = o;
        loop.quit();
    });
    loop.exec();
    EXPECT_EQ(result.failed, 0);
    EXPECT_EQ(result.results.size(), names.size());
    EXPECT_LT(result.requests, names.size() / 3);
    EXPECT_DOUBLE_EQ(result.results.value(QStringLiteral("spno2.speed")).value.number, 1000);

    // A profile that claims a block the device does not answer: one refusal, then singles;
    // the register the device really lacks is reported, the other is read.
    Profile wrong = dbu();
    ParameterMeta ghost = *dbu().parameter(QStringLiteral("spno8.direction"));
    ghost.name = QStringLiteral("ghost");
    ghost.address = 0x0321;
    wrong.parameters << ghost;
    wrong.readBlocks = {ReadBlock{3, 0x0311, 0x0321}};
    wrong.index();
    DeviceSession fallback(client.get(), wrong, 1, QStringLiteral("dbu200"));
    fallback.readMany({QStringLiteral("spno8.direction"), QStringLiteral("ghost")},
                      [&](const DeviceSession::ReadManyOutcome& o) {
                          result = o;
                          loop.quit();
                      });
    loop.exec();
    EXPECT_EQ(result.requests, 3); // the refused block, then one each
    EXPECT_EQ(result.failed, 1);
    EXPECT_TRUE(result.results.value(QStringLiteral("spno8.direction")).ok);
    EXPECT_TRUE(result.results.value(QStringLiteral("ghost")).error.contains(QStringLiteral("02")));
}
