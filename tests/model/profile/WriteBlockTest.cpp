// The profile key "writeBlock": a setting written as part of a larger 0x10 frame.
#include "model/profile/ProfileLoader.h"
#include "model/profile/ProfileRegistry.h"
#include "tests/model/profile/TestProfileJson.h"

#include <QJsonArray>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

std::optional<Profile> withBlock(const QJsonObject& block, QString* error)
{
    QJsonObject root = testProfileJson();
    QJsonArray params = root.value(QStringLiteral("parameters")).toArray();
    for (int i = 0; i < params.size(); ++i) {
        QJsonObject p = params[i].toObject();
        if (p.value(QStringLiteral("name")).toString() == QLatin1String("pid.p")) {
            p[QStringLiteral("writeBlock")] = block;
            params[i] = p;
        }
    }
    root[QStringLiteral("parameters")] = params;
    return ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), error);
}

} // namespace

TEST(WriteBlock, TheDcSerialAndGpioSettingsGoAsTheManualsOneFrameWrites)
{
    const Profile& dc = *ProfileRegistry::builtIn().family(QStringLiteral("dcpid"));
    for (const char* name : {"config.baud", "config.parity"}) {
        const BlockWrite& b = dc.parameter(QString::fromLatin1(name))->writeBlock;
        EXPECT_EQ(b.address, 0x0080) << name;
        EXPECT_EQ(b.count, 15) << name;
        EXPECT_TRUE(b.tail.isEmpty()) << name;
    }
    for (const char* name :
         {"gpio.ai1_direction", "gpio.ai2_direction", "gpio.ai1_level", "gpio.ai2_level"}) {
        const BlockWrite& b = dc.parameter(QString::fromLatin1(name))->writeBlock;
        EXPECT_EQ(b.address, 0x0050) << name;
        EXPECT_EQ(b.count, 5) << name;
        EXPECT_EQ(b.tail, (QVector<quint16>{1})) << name; // 0x0054 = 1 stores the ports
        EXPECT_EQ(b.readCount(), 4) << name;
    }
    // The lock stays a temporary 06 write: a power cycle undoes it while it is not stored.
    EXPECT_FALSE(dc.parameter(QStringLiteral("config.serial_lock"))->writeBlock.isSet());
    EXPECT_FALSE(dc.parameter(QStringLiteral("config.rated_current"))->writeBlock.isSet());
}

TEST(WriteBlock, TheLoaderChecksTheBlock)
{
    QString error;
    auto ok = withBlock({{QStringLiteral("address"), QStringLiteral("0x0090")},
                         {QStringLiteral("count"), 4},
                         {QStringLiteral("tail"), QJsonArray{7}}},
                        &error);
    ASSERT_TRUE(ok) << qPrintable(error);
    EXPECT_EQ(ok->parameter(QStringLiteral("pid.p"))->writeBlock.tail, (QVector<quint16>{7}));

    // pid.p is 0x0090–0x0091: a block whose read part ends before it is refused.
    EXPECT_FALSE(withBlock({{QStringLiteral("address"), QStringLiteral("0x0090")},
                            {QStringLiteral("count"), 2},
                            {QStringLiteral("tail"), QJsonArray{1}}},
                           &error));
    EXPECT_TRUE(error.contains(QStringLiteral("must lie in the block"))) << qPrintable(error);
    EXPECT_FALSE(withBlock(
        {{QStringLiteral("address"), QStringLiteral("0x0090")}, {QStringLiteral("count"), 200}},
        &error));
    EXPECT_TRUE(error.contains(QStringLiteral("maxWriteRegisters"))) << qPrintable(error);
    EXPECT_FALSE(withBlock({{QStringLiteral("address"), QStringLiteral("0x0090")},
                            {QStringLiteral("count"), 2},
                            {QStringLiteral("size"), 2}},
                           &error));
    EXPECT_TRUE(error.contains(QStringLiteral("unknown key"))) << qPrintable(error);
}
