#include "model/profile/ProfileRegistry.h"
#include "model/bus/BusSpec.h"
#include "model/profile/ProfileLoader.h"

#include <QDir>
#include <gtest/gtest.h>

using namespace opentop;

TEST(ProfileRegistry, BuiltInProfilesLoadAndResolveDeviceTypes)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    EXPECT_EQ(registry.families(), (QStringList{QStringLiteral("dbu"), QStringLiteral("dcpid")}));
    EXPECT_EQ(
        registry.deviceTypes(),
        (QStringList{QStringLiteral("dbu200"), QStringLiteral("dbu400"), QStringLiteral("dcpid")}));
    QString variant;
    const Profile* dbu = registry.forDeviceType(QStringLiteral("DBU400"), &variant);
    ASSERT_NE(dbu, nullptr);
    EXPECT_EQ(dbu->family, QStringLiteral("dbu"));
    EXPECT_EQ(variant, QStringLiteral("dbu400"));
    EXPECT_EQ(registry.forDeviceType(QStringLiteral("dcpid"), &variant)->family,
              QStringLiteral("dcpid"));
    EXPECT_TRUE(variant.isEmpty());
    EXPECT_EQ(registry.forDeviceType(QStringLiteral("vfd")), nullptr);
}

TEST(ProfileRegistry, EveryBuiltInFileLoadsOnItsOwn)
{
    // The same files, through the loader's file path, so a broken file names itself.
    const QDir dir(QStringLiteral(":/profiles"));
    const QStringList files = dir.entryList({QStringLiteral("*.json")});
    ASSERT_EQ(files.size(), 2);
    for (const QString& f : files) {
        QString error;
        EXPECT_TRUE(ProfileLoader::loadFile(dir.filePath(f), &error)) << qPrintable(error);
    }
}

TEST(BusSpec, ParsesListsAndRanges)
{
    QString error;
    const auto bus =
        BusSpec::parse(QStringLiteral("dbu200@1, dbu400@150,dcpid@7,dbu200@20-22"), &error);
    ASSERT_TRUE(bus) << qPrintable(error);
    ASSERT_EQ(bus->size(), 6);
    EXPECT_EQ(bus->at(1).type, QStringLiteral("dbu400"));
    EXPECT_EQ(bus->at(1).slave, 150);
    EXPECT_EQ(bus->at(5).slave, 22);
    EXPECT_EQ(BusSpec::toString(*bus),
              QStringLiteral("dbu200@1,dbu400@150,dcpid@7,dbu200@20,dbu200@21,dbu200@22"));
}

TEST(BusSpec, RejectsWithAReason)
{
    struct Case
    {
        const char* spec;
        const char* expected;
    };
    const Case cases[] = {
        {"", "empty device list"},
        {"dbu200", "write TYPE@ID"},
        {"vfd@3", "unknown device type \"vfd\"; known types: dbu200, dbu400, dcpid"},
        {"dbu200@0", "outside 1–247"},
        {"dbu200@248", "outside 1–247"},
        {"dcpid@200", "outside 1–127"},
        {"dbu200@1,dcpid@1", "machine number 1 is given twice"},
        {"dbu200@x", "must be a number or a range"},
        {"dbu200@5-2", "must be a number or a range"},
    };
    for (const Case& c : cases) {
        QString error;
        EXPECT_FALSE(BusSpec::parse(QString::fromUtf8(c.spec), &error)) << c.spec;
        EXPECT_TRUE(error.contains(QString::fromUtf8(c.expected)))
            << c.spec << ": " << qPrintable(error);
    }
}
