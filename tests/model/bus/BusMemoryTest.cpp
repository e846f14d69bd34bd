// The drives of a connection remembered per port, gateway or simulated bus.
#include "model/bus/BusMemory.h"
#include "tests/model/DriveSimFixture.h"

#include <QSettings>

using namespace opentop;
using namespace opentop::test;

namespace {
using BusMemoryTest = DriveSimFixture;
} // namespace

TEST_F(BusMemoryTest, DrivesAndTheirVariantsAreKeptPerConnection)
{
    QCoreApplication::setOrganizationName(QStringLiteral("OpenTOP-test"));
    QSettings().clear();
    ConnectionSettings serial;
    serial.port = QStringLiteral("/dev/ttyUSB0");
    ConnectionSettings tcp;
    tcp.kind = ConnectionSettings::Kind::Tcp;
    tcp.host = QStringLiteral("10.0.0.5");
    EXPECT_EQ(BusMemory::key(serial), QStringLiteral("serial:/dev/ttyUSB0"));
    EXPECT_EQ(BusMemory::key(tcp), QStringLiteral("tcp:10.0.0.5:502"));
    EXPECT_TRUE(BusMemory::load(BusMemory::key(serial)).isEmpty());

    startBus(QStringLiteral("dbu200@1,dbu400@150,dcpid@7"));
    auto drives = identifiedDrives({1, 150, 7});
    drives->setVariant(1, QStringLiteral("dbu400")); // set by hand
    DeviceInfo absent;
    absent.slave = 9;
    absent.state = DeviceInfo::State::Absent;
    drives->update(absent);
    BusMemory::save(BusMemory::key(serial), *drives);

    const QVector<BusMemory::Drive> kept = BusMemory::load(BusMemory::key(serial));
    ASSERT_EQ(kept.size(), 3); // the absent one is not remembered
    EXPECT_EQ(kept[0].slave, 1);
    EXPECT_EQ(kept[0].type, QStringLiteral("dbu400"));
    EXPECT_EQ(kept[0].model, QStringLiteral("DBU400-D4"));
    EXPECT_EQ(BusMemory::types(kept).value(7), QStringLiteral("dcpid"));
    EXPECT_TRUE(BusMemory::listText(kept).startsWith(QStringLiteral("1 (DBU400-D4), 7 (")));
    EXPECT_TRUE(BusMemory::load(BusMemory::key(tcp)).isEmpty()); // another connection
    BusMemory::forget(BusMemory::key(serial));
    EXPECT_TRUE(BusMemory::load(BusMemory::key(serial)).isEmpty());
}

// A scan of part of the bus replaces what was remembered in its range only, and the memory
// says when it was saved (the command line says a list's age before it relies on it).
TEST_F(BusMemoryTest, APartialScanReplacesItsRangeOnlyAndTheTimeIsKept)
{
    QCoreApplication::setOrganizationName(QStringLiteral("OpenTOP-test"));
    QSettings().clear();
    const QString key = QStringLiteral("serial:/dev/ttyUSB1");
    EXPECT_FALSE(BusMemory::savedAt(key).isValid());
    const auto drive = [](int slave, const char* type) {
        DeviceInfo info;
        info.slave = slave;
        info.state = DeviceInfo::State::Present;
        info.family = QString::fromLatin1(type).left(3) == QLatin1String("dbu")
                          ? QStringLiteral("dbu")
                          : QStringLiteral("dcpid");
        info.variant = QString::fromLatin1(type);
        info.model = info.variant.toUpper();
        return info;
    };
    const QDateTime before = QDateTime::currentDateTimeUtc().addSecs(-1);
    BusMemory::update(
        key, 1, 247,
        BusMemory::present({drive(1, "dbu200"), drive(5, "dbu200"), drive(30, "dbu400")}));
    ASSERT_TRUE(BusMemory::savedAt(key).isValid());
    EXPECT_GE(BusMemory::savedAt(key), before);
    // 1–10 scanned again: 5 is gone, 7 is new; 30 was not asked and stays.
    BusMemory::update(key, 1, 10, BusMemory::present({drive(1, "dbu200"), drive(7, "dcpid")}));
    QVector<int> slaves;
    for (const BusMemory::Drive& d : BusMemory::load(key))
        slaves << d.slave;
    EXPECT_EQ(slaves, QVector<int>({1, 7, 30}));
    BusMemory::forget(key);
    EXPECT_TRUE(BusMemory::load(key).isEmpty());
    EXPECT_FALSE(BusMemory::savedAt(key).isValid());
}
