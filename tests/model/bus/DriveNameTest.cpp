// Issue 24: names for machines — checked in the model, one way of naming a drive in messages,
// kept per bus for the window and the command line, carried by the drive's session.
#include "model/bus/DriveName.h"
#include "model/bus/BusDrives.h"
#include "model/bus/BusGroups.h"
#include "model/bus/BusMemory.h"
#include "model/session/DeviceSession.h"
#include "tests/model/DriveSimFixture.h"

#include <QSettings>

using namespace opentop;
using namespace opentop::test;

namespace {
using DriveNameTest = DriveSimFixture;
} // namespace

TEST(DriveName, ANameIsCheckedForLengthAndControlCharacters)
{
    EXPECT_TRUE(DriveName::problem(QStringLiteral("Infeed conveyor 3")).isEmpty());
    EXPECT_TRUE(DriveName::problem(QString()).isEmpty()) << "empty removes the name";
    EXPECT_TRUE(DriveName::problem(QStringLiteral("Förderband 3 — 搬送")).isEmpty());
    EXPECT_TRUE(DriveName::problem(QString(DriveName::kMaxLength, QLatin1Char('x'))).isEmpty());
    // Spaces at either end are not part of the name, and do not count.
    EXPECT_TRUE(
        DriveName::problem(QStringLiteral("  ") + QString(DriveName::kMaxLength, QLatin1Char('x')))
            .isEmpty());
    EXPECT_EQ(DriveName::cleaned(QStringLiteral("  Infeed 3 ")), QStringLiteral("Infeed 3"));
    const QString tooLong =
        DriveName::problem(QString(DriveName::kMaxLength + 1, QLatin1Char('x')));
    EXPECT_TRUE(tooLong.contains(QStringLiteral("at most 40 characters"))) << qPrintable(tooLong);
    for (const QString& bad :
         {QStringLiteral("Line\nfeed"), QStringLiteral("Tab\there"), QStringLiteral("Bell\x07"),
          QStringLiteral("a") + QChar(0x2028) + QStringLiteral("b"),
          QStringLiteral("a") + QChar(0x200E)})
        EXPECT_TRUE(DriveName::problem(bad).contains(QStringLiteral("control characters")))
            << qPrintable(bad);
    // "%2" in a name would be replaced in a sentence that names the drive; "50 %" is a name.
    EXPECT_TRUE(DriveName::problem(QStringLiteral("Line %2")).contains(QStringLiteral("%2")));
    EXPECT_TRUE(DriveName::problem(QStringLiteral("Mixer at 50 %")).isEmpty());
}

TEST(DriveName, MessagesNameADriveByItsNumberAndName)
{
    EXPECT_EQ(DriveName::text(1, QStringLiteral("Infeed conveyor 3")),
              QStringLiteral("machine number 1 (Infeed conveyor 3)"));
    EXPECT_EQ(DriveName::text(1, QString()), QStringLiteral("machine number 1"));
    EXPECT_EQ(DriveName::title(7, QStringLiteral("Press")),
              QStringLiteral("Machine number 7 (Press)"));
    EXPECT_EQ(DriveName::listed(7, QStringLiteral("Press")), QStringLiteral("7 (Press)"));
    EXPECT_EQ(DriveName::listed(7, QString()), QStringLiteral("7"));
    EXPECT_EQ(DriveName::withModel(1, QStringLiteral("Infeed"), QStringLiteral("DBU200-D")),
              QStringLiteral("drive 1 (Infeed, DBU200-D)"));
    EXPECT_EQ(DriveName::withModel(1, QString(), QStringLiteral("DBU200-D")),
              QStringLiteral("drive 1 (DBU200-D)"));
}

TEST_F(DriveNameTest, BusDrivesRefuseABadNameAndGiveAGoodOneToTheSessionAndTheGroups)
{
    startBus(QStringLiteral("dbu200@1,dbu200@2"));
    auto drives = identifiedDrives({1, 2});
    int named = 0;
    QObject::connect(drives.get(), &BusDrives::nameChanged, drives.get(), [&named] { ++named; });
    EXPECT_FALSE(drives->setName(1, QStringLiteral("bad\nname")).isEmpty());
    EXPECT_TRUE(drives->name(1).isEmpty());
    EXPECT_EQ(named, 0);

    EXPECT_TRUE(drives->setName(1, QStringLiteral(" Infeed conveyor 3 ")).isEmpty());
    EXPECT_EQ(drives->name(1), QStringLiteral("Infeed conveyor 3"));
    EXPECT_EQ(drives->info(1).machineName, QStringLiteral("Infeed conveyor 3"));
    EXPECT_EQ(drives->session(1)->machineName(), QStringLiteral("Infeed conveyor 3"));
    EXPECT_EQ(DriveName::text(drives->session(1)),
              QStringLiteral("machine number 1 (Infeed conveyor 3)"));
    EXPECT_EQ(drives->label(1), QStringLiteral("machine number 1 (Infeed conveyor 3)"));
    EXPECT_EQ(named, 1);
    // Identified again (a scan): the name stays with the machine number.
    DeviceInfo again = drives->info(1);
    again.machineName.clear();
    drives->update(again);
    EXPECT_EQ(drives->name(1), QStringLiteral("Infeed conveyor 3"));

    // A group question names the children by their names.
    BusGroups groups;
    groups.addDrive(1);
    groups.addDrive(2);
    groups.setGroup(2, 1);
    drives->setName(2, QStringLiteral("Outfeed"));
    groups.setNames(drives->names());
    EXPECT_TRUE(groups.alsoReachesText(1).contains(QStringLiteral("machine number 2 (Outfeed)")))
        << qPrintable(groups.alsoReachesText(1));

    EXPECT_TRUE(drives->setName(1, QString()).isEmpty());
    EXPECT_TRUE(drives->name(1).isEmpty());
    EXPECT_TRUE(drives->session(1)->machineName().isEmpty());
}

TEST_F(DriveNameTest, NamesAreKeptPerBusAndHandEditedOnesAreCheckedAgain)
{
    QCoreApplication::setOrganizationName(QStringLiteral("OpenTOP-test"));
    QSettings().clear();
    const QString key = QStringLiteral("serial:/dev/ttyUSB0");
    BusMemory::setName(key, 1, QStringLiteral("Infeed conveyor 3"));
    BusMemory::setName(key, 7, QStringLiteral("Press"));
    BusMemory::setName(QStringLiteral("tcp:10.0.0.5:502"), 1, QStringLiteral("Elsewhere"));
    QHash<int, QString> names = BusMemory::names(key);
    EXPECT_EQ(names.size(), 2);
    EXPECT_EQ(names.value(1), QStringLiteral("Infeed conveyor 3"));
    BusMemory::setName(key, 7, QString()); // removed
    EXPECT_FALSE(BusMemory::names(key).contains(7));
    // A settings file edited by hand: a name the model refuses is not taken.
    QSettings().setValue(QStringLiteral("busNames/") +
                             QString::fromLatin1(key.toUtf8().toBase64(
                                 QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals)) +
                             QStringLiteral("/2"),
                         QStringLiteral("two\nlines"));
    EXPECT_FALSE(BusMemory::names(key).contains(2));

    // The drives last seen are offered with their names.
    startBus(QStringLiteral("dbu200@1"));
    auto drives = identifiedDrives({1});
    drives->setNames(BusMemory::names(key));
    EXPECT_EQ(drives->name(1), QStringLiteral("Infeed conveyor 3"));
    BusMemory::save(key, *drives);
    EXPECT_EQ(BusMemory::listText(BusMemory::load(key)),
              QStringLiteral("1 (Infeed conveyor 3, DBU200)"));
    QSettings().clear();
}
