// Restoring backups to simulated drives in process: only what differs is written and verified,
// in dependency order with communication settings last, DC settings stored so that they
// survive a power cycle, refusals send nothing, interruptions and faults are reported exactly
// and a second run completes the restore.
#include "tests/model/files/BackupTestSupport.h"
#include "transport/MockBackend.h"
#include "transport/ModbusCrc.h"

using namespace opentop;
using namespace opentop::test;

namespace {

using Item = RestorePlan::Item;

class RestorerTest : public SimBusFixture
{
protected:
    BackupDevice factory(int slave)
    {
        const BackupReader::Result r = backup(slave);
        EXPECT_TRUE(r.ok) << qPrintable(r.failures.join(QLatin1Char('\n')));
        return r.device;
    }

    static int indexOf(const RestorePlan& plan, const QString& parameter)
    {
        for (int i = 0; i < plan.items.size(); ++i) {
            if (plan.items.at(i).parameter == parameter)
                return i;
        }
        return -1;
    }

    static const Item& item(const RestorePlan& plan, const char* parameter)
    {
        static const Item none;
        const int i = indexOf(plan, QString::fromLatin1(parameter));
        return i >= 0 ? plan.items.at(i) : none;
    }

    // Writes and stores through the bus, so that a power cycle keeps the value.
    void writeAndStore(int slave, const char* parameter, const char* value, const char* store)
    {
        DeviceSession::WriteOptions explicitly;
        explicitly.explicitCommand = true;
        for (auto [name, text] : {std::pair{parameter, value}, std::pair{store, "1"}}) {
            const auto o = waitFor<DeviceSession::Outcome>([&](auto done) {
                session(slave)->write(QString::fromLatin1(name), QString::fromLatin1(text),
                                      explicitly, done);
            });
            ASSERT_TRUE(o.ok) << qPrintable(o.error);
        }
    }

    void powerCycle(int slave)
    {
        ASSERT_TRUE(bus->control(slave, {QStringLiteral("power-cycle")}).ok);
    }
};

} // namespace

TEST_F(RestorerTest, BringsAModifiedDriveBackVerified)
{
    const BackupDevice file = factory(1);
    set(1, 0xCA03, 1500); // spno2.speed
    set(1, 0x1305, 25);   // spno3.accel 2.5 s
    set(1, 0x1007, 2500); // core.upper_limit
    const RestorePlan plan = restore(1, file);
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Done) << qPrintable(plan.reason);
    EXPECT_EQ(plan.count(Item::Status::Verified), 3);
    EXPECT_EQ(plan.count(Item::Status::Unchanged), file.parameters.size() - 3);
    EXPECT_EQ(plan.count(Item::Status::Failed), 0);
    const Item& speed = item(plan, "spno2.speed");
    EXPECT_EQ(speed.fileText, QStringLiteral("1000 r/min"));
    EXPECT_EQ(speed.deviceText, QStringLiteral("1500 r/min"));
    EXPECT_EQ(RestorePlan::statusText(speed), QStringLiteral("written and verified"));
    EXPECT_EQ(held(1, 0xCA03), 1000);
    EXPECT_EQ(held(1, 0x1305), 5);
    EXPECT_EQ(held(1, 0x1007), 3000);
}

TEST_F(RestorerTest, WritesOnlyWhatDiffersAndDryRunWritesNothing)
{
    const BackupDevice file = factory(1);
    set(1, 0xCA03, 1500);
    set(1, 0xCA05, 1600);
    int from = logSize();
    const int before = framesSent();
    const RestorePlan dry = restore(1, file, true);
    EXPECT_EQ(dry.outcome, RestorePlan::Outcome::Planned);
    EXPECT_EQ(dry.count(Item::Action::Write), 2);
    EXPECT_TRUE(writesSince(from).isEmpty());
    EXPECT_EQ(held(1, 0xCA03), 1500);
    const int reads = framesSent() - before;

    from = logSize();
    const int start = framesSent();
    const RestorePlan plan = restore(1, file);
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Done);
    EXPECT_EQ(writesSince(from), (QVector<quint16>{0xCA03, 0xCA05}));
    // The same reads as the plan, then one write and one read-back per difference.
    EXPECT_EQ(framesSent() - start, reads + 2 * 2);
    // Nothing differs any more: a second run only reads.
    from = logSize();
    const RestorePlan again = restore(1, file);
    EXPECT_EQ(again.outcome, RestorePlan::Outcome::Done);
    EXPECT_EQ(again.count(Item::Status::Verified), 0);
    EXPECT_TRUE(writesSince(from).isEmpty());
}

TEST_F(RestorerTest, WritesTheControlModeBeforeTheInputFunctions)
{
    const BackupDevice mode2 = factory(1); // Mode2: X0..X3 = CW/STOP, CCW/STOP, M0, M1
    // The drive in Mode1 with Mode1 codes: written the other way round, the drive would refuse
    // CW/STOP (0x11) as an X0 function in Mode1.
    set(1, 0x2015, 0);
    const int mode1[] = {1, 2, 5, 6};
    for (int x = 0; x < 4; ++x)
        set(1, quint16(0x2101 + 2 * x), mode1[x]);
    const BackupDevice mode1File = factory(1);
    int from = logSize();
    RestorePlan plan = restore(1, mode2);
    ASSERT_EQ(plan.outcome, RestorePlan::Outcome::Done) << qPrintable(plan.reason);
    QVector<quint16> writes = writesSince(from);
    ASSERT_EQ(writes.size(), 5);
    EXPECT_EQ(writes.first(), 0x2015);
    EXPECT_LT(indexOf(plan, QStringLiteral("core.control_mode")),
              indexOf(plan, QStringLiteral("io.x0")));
    EXPECT_EQ(held(1, 0x2101), 0x11);
    // And back to Mode1.
    from = logSize();
    plan = restore(1, mode1File);
    ASSERT_EQ(plan.outcome, RestorePlan::Outcome::Done) << qPrintable(plan.reason);
    writes = writesSince(from);
    ASSERT_EQ(writes.size(), 5);
    EXPECT_EQ(writes.first(), 0x2015);
    EXPECT_EQ(held(1, 0x2101), 1);
    EXPECT_EQ(item(plan, "io.x0").fileText, QStringLiteral("RUN/STOP"));
}

TEST_F(RestorerTest, WritesCommunicationSettingsLast)
{
    const BackupDevice file = factory(1);
    set(1, 0x1021, 4);  // comm.rate 38400 bit/s (takes effect at the next power cycle)
    set(1, 0x0401, 10); // unit.update_time 1.0 s: after comm.rate in the profile
    const int from = logSize();
    const RestorePlan plan = restore(1, file);
    ASSERT_EQ(plan.outcome, RestorePlan::Outcome::Done) << qPrintable(plan.reason);
    EXPECT_EQ(writesSince(from), (QVector<quint16>{0x0401, 0x1021}));
    EXPECT_EQ(held(1, 0x1021), 2);
    EXPECT_TRUE(plan.notes.join(QLatin1Char('\n'))
                    .contains(QStringLiteral("communication settings changed")))
        << qPrintable(plan.notes.join(QLatin1Char('\n')));
}

TEST_F(RestorerTest, ASerialLockIsReleasedFirstAndSetLast)
{
    const Profile& dc = profile("dcpid");
    BackupDevice file = factory(7);
    QHash<QString, QVector<quint16>> live;
    for (const BackupParameter& p : file.parameters)
        live.insert(p.name, p.registers);
    live[QStringLiteral("config.serial_lock")] = {1};
    live[QStringLiteral("config.baud")] = {0, 19200};
    RestorePlan plan = RestorePlan::check(dc, QString(), file);
    plan.build(dc, QString(), live);
    EXPECT_LT(indexOf(plan, QStringLiteral("config.serial_lock")),
              indexOf(plan, QStringLiteral("config.baud")));
    EXPECT_TRUE(plan.lockWarning(dc).isEmpty()) << "releasing the lock is no warning";
    // The file locks: the lock goes after the baud rate it freezes.
    for (BackupParameter& p : file.parameters) {
        if (p.name == QLatin1String("config.serial_lock"))
            p.registers = {1};
    }
    live[QStringLiteral("config.serial_lock")] = {0};
    plan = RestorePlan::check(dc, QString(), file);
    plan.build(dc, QString(), live);
    EXPECT_GT(indexOf(plan, QStringLiteral("config.serial_lock")),
              indexOf(plan, QStringLiteral("config.baud")));
    EXPECT_GT(indexOf(plan, QStringLiteral("config.baud")),
              indexOf(plan, QStringLiteral("preset.reverse_speed")));
    // Setting it is said before anything is written, with how to undo it.
    const QString lock = plan.lockWarning(dc);
    EXPECT_TRUE(lock.startsWith(QStringLiteral("config.serial_lock = Disabled")))
        << qPrintable(lock);
    EXPECT_TRUE(lock.contains(QStringLiteral("9600"))) << qPrintable(lock);
    EXPECT_TRUE(plan.notes.contains(lock));
}

TEST_F(RestorerTest, StoresDcSettingsSoThatTheySurviveAPowerCycle)
{
    const BackupDevice file = factory(7);
    writeAndStore(7, "config.rated_current", "7.5", "store.config");
    writeAndStore(7, "pid.p", "0.5", "store.pid");
    writeAndStore(7, "preset.forward_speed", "60", "store.preset");
    powerCycle(7);
    ASSERT_EQ(held(7, 0x0086), 750); // stored, so kept

    const int from = logSize();
    const RestorePlan plan = restore(7, file);
    ASSERT_EQ(plan.outcome, RestorePlan::Outcome::Done) << qPrintable(plan.reason);
    EXPECT_EQ(plan.count(Item::Action::Write), 3);
    EXPECT_EQ(plan.count(Item::Action::Store), 3);
    // The settings first, then one store command per group, in profile order.
    const QVector<quint16> writes = writesSince(from);
    ASSERT_EQ(writes.size(), 6);
    EXPECT_EQ(writes.mid(3), (QVector<quint16>{0x0180, 0x0190, 0x01A0}));
    EXPECT_EQ(RestorePlan::statusText(item(plan, "store.pid")), QStringLiteral("written"));
    powerCycle(7);
    EXPECT_EQ(held(7, 0x0086), 500);
    EXPECT_EQ(held(7, 0x0090), 15820); // 0.1 as a float, high word
    EXPECT_EQ(held(7, 0x00A2), 500);
}

TEST_F(RestorerTest, RefusesAnotherFamilyOrVariantWithNothingSent)
{
    const BackupDevice dbu200 = factory(1);
    const BackupDevice dc = factory(7);
    const int before = framesSent();
    RestorePlan plan = restore(1, dc);
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Refused);
    EXPECT_TRUE(plan.reason.contains(QStringLiteral("the file holds a dcpid drive")))
        << qPrintable(plan.reason);
    plan = restore(150, dbu200);
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Refused);
    EXPECT_TRUE(plan.reason.contains(QStringLiteral("is a DBU400-D4 (dbu400)")))
        << qPrintable(plan.reason);
    EXPECT_EQ(framesSent(), before);
}

TEST_F(RestorerTest, RefusesTheWholeFileWhenOneValueDoesNotSuitTheDrive)
{
    // 250 r/min suits a DBU200, not a DBU400: a file that does not name its variant is refused
    // for the DBU400 at 150, although every other value would do.
    BackupDevice file = factory(1);
    file.variant.clear();
    file.slave = 150;
    for (BackupParameter& p : file.parameters) {
        if (p.name == QLatin1String("spno2.speed"))
            p.registers = {250};
    }
    set(150, 0xCA05, 1600); // a difference that would otherwise be written
    const int before = framesSent();
    const RestorePlan plan = restore(150, file);
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Refused);
    ASSERT_EQ(plan.problems.size(), 1);
    EXPECT_TRUE(plan.problems.first().contains(QStringLiteral("spno2.speed: 250 r/min is not "
                                                              "allowed; allowed: 0 or 300–3000")))
        << qPrintable(plan.problems.first());
    EXPECT_EQ(framesSent(), before);
    EXPECT_EQ(held(150, 0xCA05), 1600);
}

TEST_F(RestorerTest, AnInterruptionReportsWhatWasWrittenAndASecondRunCompletes)
{
    const BackupDevice file = factory(1);
    const quint16 speeds[] = {0xCA03, 0xCA05, 0xCA07, 0xCA09, 0xCA0B};
    for (quint16 address : speeds)
        set(1, address, 2900);
    Restorer restorer(session(1));
    QObject::connect(&restorer, &Restorer::progress, &restorer,
                     [&restorer](int done, int, const QString&) {
                         if (done == 2)
                             restorer.cancel();
                     });
    const RestorePlan interrupted = restore(restorer, file);
    EXPECT_EQ(interrupted.outcome, RestorePlan::Outcome::Interrupted);
    EXPECT_EQ(interrupted.count(Item::Status::Verified), 2);
    EXPECT_EQ(interrupted.count(Item::Status::NotAttempted), 3);
    EXPECT_TRUE(interrupted.reason.contains(QStringLiteral("after 2 of 5 writes")))
        << qPrintable(interrupted.reason);
    EXPECT_EQ(RestorePlan::statusText(item(interrupted, "spno4.speed")),
              QStringLiteral("not attempted"));
    EXPECT_EQ(held(1, 0xCA03), 1000);
    EXPECT_EQ(held(1, 0xCA07), 2900);

    const RestorePlan second = restore(1, file);
    EXPECT_EQ(second.outcome, RestorePlan::Outcome::Done);
    EXPECT_EQ(second.count(Item::Status::Verified), 3);
    EXPECT_EQ(held(1, 0xCA0B), 2500);
}

TEST_F(RestorerTest, AnInterruptionBeforeStoringIsCompletedByTheNextRun)
{
    const BackupDevice file = factory(7);
    writeAndStore(7, "config.rated_current", "7.5", "store.config");
    Restorer restorer(session(7));
    QObject::connect(&restorer, &Restorer::progress, &restorer,
                     [&restorer](int, int, const QString&) { restorer.cancel(); });
    const RestorePlan interrupted = restore(restorer, file);
    EXPECT_EQ(interrupted.outcome, RestorePlan::Outcome::Interrupted);
    EXPECT_EQ(item(interrupted, "config.rated_current").status, Item::Status::Verified);
    EXPECT_EQ(item(interrupted, "store.config").status, Item::Status::NotAttempted);
    // The value is right but not stored; the next run has nothing to write and still stores.
    const RestorePlan second = restore(7, file);
    EXPECT_EQ(second.outcome, RestorePlan::Outcome::Done);
    EXPECT_EQ(second.count(Item::Action::Write), 0);
    EXPECT_EQ(item(second, "store.config").status, Item::Status::Verified);
    powerCycle(7);
    EXPECT_EQ(held(7, 0x0086), 500);
}

TEST_F(RestorerTest, InjectedFaultsAreReportedAndTheRestCompletesLater)
{
    const BackupDevice file = factory(1);
    set(1, 0xCA03, 1500);
    set(1, 0xCA05, 1600);
    set(1, 0xCA07, 1800);
    Restorer restorer(session(1));
    QObject::connect(&restorer, &Restorer::progress, &restorer,
                     [this](int done, int, const QString&) {
                         if (done == 1) {
                             FaultInjector::Rates rates;
                             rates.drop = 1.0; // every reply lost from now on
                             bus->setFaults(FaultInjector(rates, 7));
                         }
                     });
    const RestorePlan failed = restore(restorer, file);
    EXPECT_EQ(failed.outcome, RestorePlan::Outcome::Communication);
    EXPECT_EQ(failed.count(Item::Status::Verified), 1);
    EXPECT_EQ(failed.count(Item::Status::Failed), 0);
    EXPECT_EQ(failed.count(Item::Status::NotAttempted), 1);
    // The drive executed the write and only its reply was lost: not "failed", not confirmed.
    const Item& lost = item(failed, "spno3.speed");
    EXPECT_EQ(lost.status, Item::Status::NotConfirmed);
    EXPECT_FALSE(lost.error.isEmpty());
    EXPECT_FALSE(lost.mismatch);
    EXPECT_TRUE(failed.reason.startsWith(QStringLiteral("spno3.speed not confirmed")))
        << qPrintable(failed.reason);

    bus->setFaults(FaultInjector());
    const RestorePlan second = restore(1, file);
    EXPECT_EQ(second.outcome, RestorePlan::Outcome::Done) << qPrintable(second.reason);
    EXPECT_EQ(held(1, 0xCA07), 1700);
    EXPECT_EQ(held(1, 0xCA05), 1350);
}

TEST_F(RestorerTest, AFailedReadWritesNothing)
{
    BackupDevice file = factory(1);
    // One setting keeps the test short: every request times out.
    file.parameters = {*file.parameter(QStringLiteral("spno2.speed"))};
    set(1, 0xCA03, 1500);
    FaultInjector::Rates rates;
    rates.drop = 1.0;
    bus->setFaults(FaultInjector(rates, 3));
    const int from = logSize();
    const RestorePlan plan = restore(1, file);
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Communication);
    EXPECT_TRUE(plan.reason.startsWith(QStringLiteral("reading the drive failed, nothing written")))
        << qPrintable(plan.reason);
    EXPECT_TRUE(writesSince(from).isEmpty());
    EXPECT_EQ(plan.count(Item::Status::NotAttempted), plan.items.size());
}

TEST_F(RestorerTest, AValueTheDriveDoesNotKeepIsAMismatchAndTheRestContinues)
{
    const BackupDevice file = factory(1);
    set(1, 0xCA03, 1500);
    set(1, 0xCA05, 1600);
    // A drive that acknowledges SPno2 speed writes but keeps 1200 r/min instead.
    auto backend = std::make_unique<MockBackend>([this](const QByteArray& adu) {
        const bool speed2 = adu.size() == 8 && quint8(adu.at(1)) == 0x06 &&
                            quint8(adu.at(2)) == 0xCA && quint8(adu.at(3)) == 0x03;
        if (!speed2)
            return bus->handleFrame(adu).reply;
        QByteArray clamped = adu.left(4);
        clamped.append(char(1200 >> 8)).append(char(1200 & 0xFF));
        bus->handleFrame(ModbusCrc::append(clamped));
        return adu; // the echo a write gets
    });
    ModbusClient stubborn(std::move(backend), client->settings());
    ASSERT_TRUE(stubborn.openBlocking().isEmpty());
    DeviceSession drive(&stubborn, profile("dbu"), 1, QStringLiteral("dbu200"));
    Restorer restorer(&drive);
    const RestorePlan plan = restore(restorer, file);
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Mismatch);
    const Item& speed2 = item(plan, "spno2.speed");
    EXPECT_EQ(speed2.status, Item::Status::Failed);
    EXPECT_TRUE(speed2.mismatch);
    EXPECT_TRUE(speed2.error.contains(QStringLiteral("1200 r/min"))) << qPrintable(speed2.error);
    EXPECT_EQ(item(plan, "spno3.speed").status, Item::Status::Verified);
    EXPECT_EQ(held(1, 0xCA05), 1350);
}

TEST_F(RestorerTest, APortVanishingDuringAWriteLeavesItNotConfirmedAndTheNextRunReadsItBack)
{
    const BackupDevice file = factory(1);
    set(1, 0xCA03, 1500);
    set(1, 0xCA05, 1600);
    Restorer restorer(session(1));
    QObject::connect(&restorer, &Restorer::progress, &restorer,
                     [this](int done, int, const QString&) {
                         if (done == 1)
                             bus->setUnplugged(true);
                     });
    const RestorePlan failed = restore(restorer, file);
    EXPECT_EQ(failed.outcome, RestorePlan::Outcome::Communication);
    const Item& inFlight = item(failed, "spno3.speed");
    EXPECT_EQ(inFlight.status, Item::Status::NotConfirmed);
    const QString text = RestorePlan::statusText(inFlight);
    EXPECT_TRUE(text.startsWith(QStringLiteral("not confirmed"))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("may or may not hold it"))) << qPrintable(text);
    EXPECT_FALSE(text.contains(QStringLiteral("failed"))) << qPrintable(text);
    EXPECT_EQ(RestorePlan::statusKey(inFlight.status), QStringLiteral("not-confirmed"));

    // The re-run reads the drive first: what it holds decides, then the rest is written.
    bus->setUnplugged(false);
    ASSERT_TRUE(client->openBlocking().isEmpty()); // plugged in again
    const int from = logSize();
    const RestorePlan second = restore(1, file);
    EXPECT_EQ(second.outcome, RestorePlan::Outcome::Done) << qPrintable(second.reason);
    EXPECT_TRUE(second.deviceRead);
    EXPECT_EQ(held(1, 0xCA05), 1350);
    EXPECT_FALSE(writesSince(from).isEmpty());
}

TEST_F(RestorerTest, AFailedReadIsMarkedAsNotRead)
{
    BackupDevice file = factory(1);
    file.parameters = {*file.parameter(QStringLiteral("spno2.speed"))};
    bus->setUnplugged(true);
    const RestorePlan plan = restore(1, file);
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Communication);
    EXPECT_FALSE(plan.deviceRead); // nothing compared: no "0 of N settings differ"
    bus->setUnplugged(false);
    ASSERT_TRUE(client->openBlocking().isEmpty());
    EXPECT_TRUE(restore(1, file).deviceRead);
}

// Issue 24: a store command is sent only when something written needs it, and the plan says so.
TEST_F(RestorerTest, NothingDifferentNothingStoredAndSaidSo)
{
    const BackupDevice file = factory(7);
    const int from = logSize();
    const RestorePlan plan = restore(7, file);
    ASSERT_EQ(plan.outcome, RestorePlan::Outcome::Done) << qPrintable(plan.reason);
    EXPECT_EQ(plan.count(Item::Action::Write), 0);
    EXPECT_EQ(plan.count(Item::Action::Store), 0);
    EXPECT_TRUE(writesSince(from).isEmpty()) << "no store command for nothing";
    const QString notes = plan.notes.join(QLatin1Char('\n'));
    EXPECT_TRUE(notes.contains(QStringLiteral("not sent: nothing it stores is written")))
        << qPrintable(notes);
}

TEST_F(RestorerTest, OnlyTheGroupWrittenIsStored)
{
    const BackupDevice file = factory(7);
    writeAndStore(7, "pid.p", "0.5", "store.pid"); // stored: differs from the file now
    const int from = logSize();
    const RestorePlan plan = restore(7, file);
    ASSERT_EQ(plan.outcome, RestorePlan::Outcome::Done) << qPrintable(plan.reason);
    EXPECT_EQ(plan.count(Item::Action::Write), 1);
    // The PID settings are stored; the configuration and the preset speeds were not touched.
    const QVector<quint16> writes = writesSince(from);
    ASSERT_EQ(writes.size(), 2);
    EXPECT_EQ(writes.last(), 0x0190);
    EXPECT_EQ(item(plan, "store.pid").status, Item::Status::Verified);
    const QString notes = plan.notes.join(QLatin1Char('\n'));
    EXPECT_TRUE(notes.contains(QStringLiteral("sent after the writes"))) << qPrintable(notes);
    powerCycle(7);
    EXPECT_EQ(held(7, 0x0090), 15820); // 0.1 as a float, high word: kept over power-off
}
