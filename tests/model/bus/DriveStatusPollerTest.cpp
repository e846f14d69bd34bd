#include "model/bus/DriveStatusPoller.h"
#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "sim/SimBackend.h"
#include "sim/SimBus.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <functional>
#include <gtest/gtest.h>
#include <memory>

using namespace opentop;
using Led = DriveStatus::Led;

namespace {

bool waitFor(const std::function<bool()>& condition, int ms = 5000)
{
    QDeadlineTimer deadline(ms);
    while (!condition() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    return condition();
}

class DriveStatusPollerTest : public ::testing::Test
{
protected:
    // `spec` on the bus; `listed` are put into BusDrives as identified (family by id).
    void start(const QString& spec, const QVector<QPair<int, QString>>& listed)
    {
        QString error;
        bus = SimBus::fromSpec(spec, &error);
        ASSERT_TRUE(bus) << qPrintable(error);
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.simSpec = spec;
        settings.timeoutMs = 50;
        settings.retries = 0;
        client = std::make_unique<ModbusClient>(std::make_unique<SimBackend>(bus), settings);
        bool opened = false;
        QObject::connect(client.get(), &ModbusClient::opened,
                         [&](bool ok, const QString&) { opened = ok; });
        client->open();
        ASSERT_TRUE(waitFor([&] { return opened; }));
        drives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
        for (const auto& [slave, family] : listed) {
            DeviceInfo info;
            info.slave = slave;
            info.state = DeviceInfo::State::Present;
            info.family = family;
            drives->update(info);
        }
        poller = std::make_unique<DriveStatusPoller>(drives.get());
        poller->setInterval(20);
    }

    void TearDown() override
    {
        poller.reset();
        drives.reset();
        client.reset();
    }

    bool waitForLed(int slave, Led led, int ms = 5000)
    {
        return waitFor([&] { return poller->status(slave).led == led; }, ms);
    }

    DeviceSession::Outcome write(int slave, const char* name, const QString& text)
    {
        DeviceSession::WriteOptions explicitly;
        explicitly.explicitCommand = true;
        DeviceSession::Outcome result;
        bool done = false;
        drives->session(slave)->write(QLatin1String(name), text, explicitly,
                                      [&](const DeviceSession::Outcome& o) {
                                          result = o;
                                          done = true;
                                      });
        EXPECT_TRUE(waitFor([&] { return done; }));
        return result;
    }

    std::shared_ptr<SimBus> bus;
    std::unique_ptr<ModbusClient> client;
    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<DriveStatusPoller> poller;
};

} // namespace

TEST_F(DriveStatusPollerTest, StoppedDrivesAreGreenAndAnAbsentOneGrey)
{
    start(QStringLiteral("dbu200@1,dcpid@7"),
          {{1, QStringLiteral("dbu")}, {7, QStringLiteral("dcpid")}, {9, QStringLiteral("dbu")}});
    EXPECT_EQ(poller->parametersFor(7), QStringList{QStringLiteral("status.pwm")});
    int changes = 0;
    QObject::connect(poller.get(), &DriveStatusPoller::statusChanged, [&](int) { ++changes; });
    poller->start();
    ASSERT_TRUE(waitFor([&] { return poller->cyclesCompleted() >= 2; }));
    EXPECT_GE(changes, 6);

    const DriveStatus dbu = poller->status(1);
    EXPECT_TRUE(dbu.online());
    EXPECT_EQ(dbu.led, Led::Green);
    EXPECT_EQ(dbu.running, false);
    EXPECT_EQ(dbu.alarmActive, false);
    EXPECT_EQ(dbu.priorityText, QStringLiteral("I/O priority"));
    EXPECT_EQ(dbu.motionPriority, false);

    const DriveStatus dc = poller->status(7);
    EXPECT_EQ(dc.led, Led::Green);
    EXPECT_EQ(dc.running, false);
    EXPECT_FALSE(dc.alarmActive.has_value()); // the DC controller reports no alarm flag
    EXPECT_TRUE(dc.priorityText.isEmpty());

    const DriveStatus absent = poller->status(9);
    EXPECT_EQ(absent.led, Led::Grey);
    EXPECT_FALSE(absent.online());
    EXPECT_GE(absent.consecutiveFailures, 2);
    EXPECT_TRUE(absent.communicationText().contains(QStringLiteral("no answer")))
        << qPrintable(absent.communicationText());
    EXPECT_FALSE(absent.error.isEmpty());
    poller->stop();
    EXPECT_FALSE(poller->isActive());
}

TEST_F(DriveStatusPollerTest, AlarmsFollowTheDbuLedColours)
{
    start(QStringLiteral("dbu200@1,dbu200@2,dbu200@3"),
          {{1, QStringLiteral("dbu")}, {2, QStringLiteral("dbu")}, {3, QStringLiteral("dbu")}});
    ASSERT_TRUE(bus->control(1, {QStringLiteral("alarm"), QStringLiteral("7")}).ok);
    ASSERT_TRUE(bus->control(2, {QStringLiteral("alarm"), QStringLiteral("13")}).ok);
    ASSERT_TRUE(bus->control(3, {QStringLiteral("alarm"), QStringLiteral("15")}).ok);
    poller->start();
    ASSERT_TRUE(waitForLed(1, Led::Red));
    ASSERT_TRUE(waitForLed(2, Led::Blue));
    ASSERT_TRUE(waitForLed(3, Led::Purple));
    EXPECT_EQ(poller->status(1).alarmCode, 7);
    EXPECT_EQ(poller->status(1).ledText(), QStringLiteral("Alarm AL007 Overload"));
    EXPECT_TRUE(poller->status(2).ledText().contains(QStringLiteral("AL00D")));
    EXPECT_TRUE(poller->status(3).ledText().contains(QStringLiteral("AL00F")));
}

TEST_F(DriveStatusPollerTest, RunningDirectionSetsOrangeOrSkyBlue)
{
    start(QStringLiteral("dbu200@1,dcpid@7"),
          {{1, QStringLiteral("dbu")}, {7, QStringLiteral("dcpid")}});
    poller->start();
    ASSERT_TRUE(waitForLed(1, Led::Green));
    ASSERT_TRUE(write(1, "core.control_priority", QStringLiteral("2")).ok);
    ASSERT_TRUE(waitFor([&] { return poller->status(1).motionPriority == true; }));
    EXPECT_EQ(poller->status(1).priorityText, QStringLiteral("Communication priority"));
    // Selecting running data resets the direction to the data's own: direction after select.
    ASSERT_TRUE(write(1, "run.select", QStringLiteral("SPno2")).ok);
    ASSERT_TRUE(write(1, "run.direction", QStringLiteral("CCW")).ok);
    ASSERT_TRUE(write(1, "run.start", QStringLiteral("START")).ok);
    ASSERT_TRUE(waitForLed(1, Led::SkyBlue))
        << qPrintable(DriveStatus::ledName(poller->status(1).led) + QStringLiteral(": ") +
                      poller->status(1).ledText());
    EXPECT_EQ(poller->status(1).ledText(), QStringLiteral("Running CCW"));

    // The DC controller runs when its PWM is not zero; it tells no direction flag.
    const DeviceSession::Outcome pwm = write(7, "speed.command", QStringLiteral("50"));
    ASSERT_TRUE(pwm.ok) << qPrintable(pwm.error);
    ASSERT_TRUE(waitForLed(7, Led::Orange));
    EXPECT_EQ(poller->status(7).ledText(), QStringLiteral("Running"));
}

TEST(DriveStatusLedTest, CommunicationFailuresAreBlueThenGrey)
{
    DriveStatus s;
    EXPECT_EQ(DriveStatusPoller::ledFor(s), Led::Grey); // not polled yet
    s.polled = true;
    s.answered = true;
    s.running = true;
    s.reverse = false;
    EXPECT_EQ(DriveStatusPoller::ledFor(s), Led::Orange);
    s.consecutiveFailures = 1;
    EXPECT_EQ(DriveStatusPoller::ledFor(s), Led::Blue);
    s.consecutiveFailures = DriveStatus::kNoAnswerAfter;
    EXPECT_EQ(DriveStatusPoller::ledFor(s), Led::Grey);
    s.consecutiveFailures = 0;
    s.alarmActive = true;
    s.alarmCode = 0x0F; // no table entry: the DBU's own rule
    EXPECT_EQ(DriveStatusPoller::ledFor(s), Led::Purple);
    s.alarmCode = 0x0D;
    EXPECT_EQ(DriveStatusPoller::ledFor(s), Led::Blue);
    s.alarmCode = 0x07;
    EXPECT_EQ(DriveStatusPoller::ledFor(s), Led::Red);
}

// The DBU's seven-colour LED table (manual chapter 4, "MONITOR Status indicator") is profile
// data: each state the program derives takes the profile's colour, name and meaning.
TEST(DriveStatusLedTest, TheProfilesTableGivesColourNameAndMeaning)
{
    const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    ASSERT_EQ(dbu.statusLed.size(), 7);
    const struct
    {
        Led led;
        const char* colour;
        const char* meaning;
    } table[] = {
        {Led::Red, "#e51c23", "Alarm"},
        {Led::Green, "#2eb83c", "Run / edit"},
        {Led::Orange, "#ff8c00", "CW"},
        {Led::SkyBlue, "#4fc3f7", "CCW"},
        {Led::Purple, "#9c27b0", "External interrupt"},
        {Led::Blue, "#154dd6", "Memory, CPU or communication"},
    };
    for (const auto& t : table) {
        const StatusLedEntry* e = dbu.ledEntry(DriveStatus::ledLight(t.led));
        ASSERT_NE(e, nullptr) << t.colour;
        EXPECT_EQ(e->colour, QString::fromLatin1(t.colour));
        EXPECT_TRUE(e->meaning.contains(QString::fromLatin1(t.meaning))) << qPrintable(e->meaning);
    }
    ASSERT_NE(dbu.ledEntry(QStringLiteral("white")), nullptr); // no power: listed, never derived
    EXPECT_TRUE(dbu.ledEntry(QStringLiteral("red"))->blink.contains(QStringLiteral("Flashes")));

    DriveStatus s;
    s.polled = s.answered = true;
    s.running = true;
    s.reverse = true;
    Profile edited = dbu;
    for (StatusLedEntry& e : edited.statusLed) {
        if (e.light == QLatin1String("skyBlue")) {
            e.colour = QStringLiteral("#123456");
            e.label = QStringLiteral("Teal");
        }
    }
    DriveStatusPoller::applyLed(&s, &edited);
    EXPECT_EQ(s.led, Led::SkyBlue);
    ASSERT_TRUE(s.ledEntry);
    EXPECT_EQ(s.ledEntry->colour, QStringLiteral("#123456"));
    EXPECT_EQ(s.ledLabel(Led::SkyBlue), QStringLiteral("Teal"));
    EXPECT_EQ(s.ledLabel(Led::Grey), DriveStatus::ledName(Led::Grey)); // shown grey: not live
    EXPECT_TRUE(s.ledManualText().contains(QStringLiteral("CCW")));
    // Without a table (the DC controller's profile): no entry, the program's names.
    DriveStatusPoller::applyLed(&s, ProfileRegistry::builtIn().family(QStringLiteral("dcpid")));
    EXPECT_FALSE(s.ledEntry);
    EXPECT_EQ(s.ledLabel(Led::SkyBlue), DriveStatus::ledName(Led::SkyBlue));
    DriveStatusPoller::applyLed(&s, nullptr);
    EXPECT_FALSE(s.ledEntry);
}
