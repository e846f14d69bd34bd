#include "model/eol/UnitRecordJson.h"
#include "tests/support/EolSampleUnit.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <gtest/gtest.h>

using namespace opentop;

TEST(UnitRecordJsonTest, RoundTripKeepsEverything)
{
    for (UnitStatus status : {UnitStatus::Pass, UnitStatus::Fail, UnitStatus::Aborted}) {
        UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-1"), status);
        r.id = QStringLiteral("a0b1c2");
        QString error;
        const auto back = UnitRecordJson::fromBytes(UnitRecordJson::toBytes(r), &error);
        ASSERT_TRUE(back) << error.toStdString();
        EXPECT_EQ(*back, r);
        EXPECT_EQ(UnitRecordJson::toBytes(*back), UnitRecordJson::toBytes(r));
    }
}

TEST(UnitRecordJsonTest, LimitThatIsNotSetIsAbsentAndTimesAreUtcWithMilliseconds)
{
    const QJsonObject json = UnitRecordJson::toJson(test::eolSampleUnit(QStringLiteral("SN-2")));
    EXPECT_EQ(json.value(QStringLiteral("started")).toString(),
              QStringLiteral("2026-11-24T13:05:07.123Z"));
    const QJsonObject load = json.value(QStringLiteral("measurements")).toArray().at(1).toObject();
    EXPECT_FALSE(load.contains(QStringLiteral("lower")));
    EXPECT_EQ(load.value(QStringLiteral("upper")).toDouble(), 120.0);
    EXPECT_EQ(json.value(QStringLiteral("status")).toString(), QStringLiteral("fail"));
}

TEST(UnitRecordJsonTest, RefusesWhatIsNotAKnownRecord)
{
    QJsonObject json = UnitRecordJson::toJson(test::eolSampleUnit(QStringLiteral("SN-3")));
    QString error;
    QJsonObject other = json;
    other.insert(QStringLiteral("format"), QStringLiteral("opentop-backup"));
    EXPECT_FALSE(UnitRecordJson::fromJson(other, &error));
    EXPECT_TRUE(error.contains(QLatin1String("opentop-unit-record")));
    QJsonObject newer = json;
    newer.insert(QStringLiteral("version"), UnitRecordJson::kFormatVersion + 1);
    EXPECT_FALSE(UnitRecordJson::fromJson(newer, &error));
    EXPECT_TRUE(error.contains(QLatin1String("version"))) << error.toStdString();
    QJsonObject status = json;
    status.insert(QStringLiteral("status"), QStringLiteral("passed"));
    EXPECT_FALSE(UnitRecordJson::fromJson(status, &error));
    EXPECT_TRUE(error.contains(QLatin1String("passed")));
    QJsonObject noSerial = json;
    noSerial.remove(QStringLiteral("serial"));
    EXPECT_FALSE(UnitRecordJson::fromJson(noSerial, &error));
    EXPECT_FALSE(UnitRecordJson::fromBytes("{not json", &error));
}
