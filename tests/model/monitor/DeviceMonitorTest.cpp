// The live monitor against the in-process simulated bus.
#include "model/monitor/DeviceMonitor.h"
#include "tests/model/DriveSimFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class DeviceMonitorTest : public DriveSimFixture
{
protected:
    // Starts `monitor` and collects `count` samples (or errors).
    QVector<MonitorSample> collect(DeviceMonitor& monitor, int count, QStringList* errors = nullptr)
    {
        QVector<MonitorSample> samples;
        QStringList errs;
        QObject::connect(&monitor, &DeviceMonitor::sample, &monitor,
                         [&](const QDateTime&, const MonitorSample& s) { samples << s; });
        QObject::connect(&monitor, &DeviceMonitor::error, &monitor,
                         [&](const QString& e) { errs << e; });
        monitor.start();
        EXPECT_TRUE(waitUntil([&] { return samples.size() + errs.size() >= count; }, 10000));
        monitor.stop();
        QObject::disconnect(&monitor, nullptr, &monitor, nullptr);
        if (errors)
            *errors = errs;
        return samples;
    }

    void prepare(DeviceMonitor& monitor)
    {
        const QString error = await<QString>([&](auto done) { monitor.prepare(done); });
        EXPECT_TRUE(error.isEmpty()) << qPrintable(error);
    }
};

} // namespace

TEST_F(DeviceMonitorTest, SamplesCarryDecodedValuesAndRoles)
{
    startBus(QStringLiteral("dbu200@1"));
    DeviceMonitor monitor(session(1));
    monitor.setInterval(50);
    EXPECT_EQ(monitor.parameters().first(), QStringLiteral("status.current_speed"));
    prepare(monitor);
    ASSERT_TRUE(monitor.speedDisplay());
    QElapsedTimer timer;
    timer.start();
    const QVector<MonitorSample> samples = collect(monitor, 3);
    ASSERT_GE(samples.size(), 3);
    EXPECT_GE(timer.elapsed(), 100); // three polls 50 ms apart
    const MonitorSample& s = samples.first();
    EXPECT_EQ(s.slave, 1);
    EXPECT_TRUE(s.timestamp.isValid());
    EXPECT_EQ(s.values.size(), monitor.parameters().size());
    for (const char* name :
         {"status.current_speed", "status.load", "status.driver", "core.control_priority"})
        ASSERT_NE(s.find(QString::fromLatin1(name)), nullptr) << name;
    EXPECT_EQ(s.find(QStringLiteral("status.current_speed"))->text, QStringLiteral("0 r/min"));
    EXPECT_EQ(s.find(QStringLiteral("status.load"))->text, QStringLiteral("0 %"));
    EXPECT_EQ(s.find(QStringLiteral("core.control_priority"))->text,
              QStringLiteral("I/O priority"));
    EXPECT_EQ(s.running, std::optional<bool>(false));
    EXPECT_EQ(s.alarmActive, std::optional<bool>(false));
    EXPECT_FALSE(s.activeAlarm);
    ASSERT_TRUE(s.currentShown);
    EXPECT_EQ(s.currentShown->text, QStringLiteral("0.000"));
    EXPECT_LE(samples[0].timestamp.msecsTo(samples[1].timestamp), 200);
}

TEST_F(DeviceMonitorTest, DisplayFollowsTheDrivesUnitSettingsAndDirection)
{
    startBus(QStringLiteral("dbu200@1"));
    // Linear speed in m/min, 1000.0 mm diameter, reduction 5.00: 500 r/min -> 100 r/min ->
    // 314.159.
    control(1, {QStringLiteral("set"), QStringLiteral("0x0409"), QStringLiteral("2")});
    control(1, {QStringLiteral("set"), QStringLiteral("0x040F"), QStringLiteral("10000")});
    control(1, {QStringLiteral("set"), QStringLiteral("0x0404"), QStringLiteral("500")});
    // Running CCW in I/O priority: X1 = CCW/STOP, SPno1 at the Ext-VR's 500 r/min.
    control(1, {QStringLiteral("input"), QStringLiteral("2")});
    DeviceMonitor monitor(session(1));
    monitor.setInterval(50);
    prepare(monitor);
    ASSERT_TRUE(monitor.speedDisplay());
    EXPECT_EQ(monitor.speedDisplay()->unit(), QStringLiteral("m/min"));
    ASSERT_TRUE(waitUntil([&] {
        const QVector<MonitorSample> s = collect(monitor, 1);
        return !s.isEmpty() &&
               s.first().find(QStringLiteral("status.current_speed"))->value.number == 500;
    }));
    const MonitorSample s = collect(monitor, 1).value(0);
    EXPECT_EQ(s.running, std::optional<bool>(true));
    EXPECT_EQ(s.signedSpeed(QStringLiteral("status.current_speed")), std::optional<double>(-500));
    ASSERT_TRUE(s.currentShown);
    EXPECT_EQ(s.currentShown->text, QStringLiteral("-314.159"));
    EXPECT_EQ(s.targetShown->text, QStringLiteral("-314.159"));
}

TEST_F(DeviceMonitorTest, ActiveAlarmIsNamedFromTheCodeTable)
{
    startBus(QStringLiteral("dbu200@1"));
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    DeviceMonitor monitor(session(1));
    monitor.setInterval(50);
    const QVector<MonitorSample> samples = collect(monitor, 2);
    ASSERT_EQ(samples.size(), 2);
    for (const MonitorSample& s : samples) {
        EXPECT_EQ(s.alarmActive, std::optional<bool>(true));
        ASSERT_TRUE(s.activeAlarm);
        EXPECT_EQ(s.activeAlarm->panel, QStringLiteral("AL007"));
        EXPECT_EQ(s.activeAlarm->name, QStringLiteral("Overload"));
    }
}

TEST_F(DeviceMonitorTest, DcControllerSamplesItsOwnMonitorList)
{
    startBus(QStringLiteral("dcpid@7"));
    DeviceMonitor monitor(session(7));
    monitor.setInterval(50);
    prepare(monitor);
    EXPECT_FALSE(monitor.speedDisplay());
    const int before = framesSent();
    const QVector<MonitorSample> samples = collect(monitor, 2);
    ASSERT_EQ(samples.size(), 2);
    EXPECT_EQ(framesSent() - before, 2); // 0x0010..0x001A in one request per poll
    const MonitorSample& s = samples.first();
    EXPECT_EQ(s.find(QStringLiteral("status.pwm"))->text, QStringLiteral("0.0 %"));
    EXPECT_EQ(s.find(QStringLiteral("status.current"))->text, QStringLiteral("0.00 A"));
    EXPECT_EQ(s.find(QStringLiteral("status.sq1_level"))->text, QStringLiteral("Low"));
    EXPECT_EQ(s.running, std::optional<bool>(false));
    EXPECT_FALSE(s.alarmActive);
    EXPECT_FALSE(s.currentShown);
}

TEST_F(DeviceMonitorTest, ADriveThatDoesNotAnswerGivesErrors)
{
    startBus(QStringLiteral("dbu200@1"));
    DeviceMonitor monitor(session(42));
    monitor.setInterval(50);
    QStringList errors;
    const QVector<MonitorSample> samples = collect(monitor, 1, &errors);
    EXPECT_TRUE(samples.isEmpty());
    ASSERT_EQ(errors.size(), 1);
    EXPECT_TRUE(errors.first().startsWith(QStringLiteral("machine number 42:")))
        << qPrintable(errors.first());
    EXPECT_TRUE(errors.first().contains(QStringLiteral("timeout"), Qt::CaseInsensitive));
}

TEST_F(DeviceMonitorTest, PollsGiveWayToUserRequests)
{
    // With wire timing at 9600 bit/s each transaction takes tens of ms, so the poll's requests
    // queue up behind each other.
    startBus(QStringLiteral("dbu200@1"), 9600);
    DeviceMonitor monitor(session(1));
    monitor.setInterval(50);
    monitor.start();
    // The poll's first request is on the wire, the others queued at Poll priority.
    ModbusRequest user = ModbusRequest::readHolding(1, 0xCA03, 1);
    user.priority = ModbusRequest::Priority::User;
    bool answered = false;
    client->submit(user, nullptr, [&](const ModbusResult& r) { answered = r.ok(); });
    ASSERT_TRUE(waitUntil([&] { return answered && framesSent() >= 3; }));
    monitor.stop();
    QVector<quint16> order; // addresses of the requests in the order they were sent
    for (const TrafficEntry& e : log.entries()) {
        if (e.direction == TrafficEntry::Direction::Tx && e.bytes.size() >= 4)
            order << quint16((quint8(e.bytes[2]) << 8) | quint8(e.bytes[3]));
    }
    const int userAt = order.indexOf(0xCA03);
    ASSERT_GE(userAt, 0);
    EXPECT_LE(userAt, 1) << "the user request waited behind queued polling";
    EXPECT_GT(order.size(), userAt + 1); // polling went on after it
}
