#include "model/traffic/TrafficDescriber.h"
#include "tests/model/DriveSimFixture.h"

#include "model/bus/BusGroups.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusRequest.h"
#include "transport/RtuFrame.h"

using namespace opentop;
using namespace opentop::test;

namespace {

const Profile* dbu()
{
    return ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
}

TrafficEntry entryFor(TrafficEntry::Direction direction, const ModbusRequest& request,
                      const QByteArray& bytes, const QString& summary)
{
    TrafficEntry e;
    e.direction = direction;
    e.slave = request.slave;
    e.function = request.function;
    e.bytes = bytes;
    e.summary = summary;
    return e;
}

TrafficDescriber dbuAt(int slave)
{
    return TrafficDescriber([slave](int s) { return s == slave ? dbu() : nullptr; });
}

} // namespace

TEST(TrafficDescriberTest, NamesTheParameterOfARead)
{
    const ModbusRequest r = ModbusRequest::readHolding(1, 0xCA03, 1);
    const TrafficEntry tx =
        entryFor(TrafficEntry::Direction::Tx, r, RtuFrame::encodeRequest(r), r.describe());
    EXPECT_EQ(dbuAt(1).describe(tx, &r), r.describe() + QStringLiteral(" (spno2.speed)"));
}

TEST(TrafficDescriberTest, AFrameAskingMoreThanModbusAllowsNamesNoParameter)
{
    // 126 registers from 0xCA03 would cover spno2.speed, but no drive answers such a read
    const ModbusRequest tooMany = ModbusRequest::readHolding(1, 0xCA03, 126);
    const TrafficEntry tx = entryFor(TrafficEntry::Direction::Tx, tooMany,
                                     RtuFrame::encodeRequest(tooMany), tooMany.describe());
    EXPECT_EQ(dbuAt(1).describe(tx, &tooMany), QString());
    const ModbusRequest most = ModbusRequest::readHolding(1, 0xCA03, 125);
    const TrafficEntry ok =
        entryFor(TrafficEntry::Direction::Tx, most, RtuFrame::encodeRequest(most), most.describe());
    EXPECT_TRUE(dbuAt(1).describe(ok, &most).contains(QStringLiteral("spno2.speed")));
}

TEST(TrafficDescriberTest, DecodesTheReplyValueWithItsUnit)
{
    const ModbusRequest r = ModbusRequest::readHolding(1, 0xCA03, 1);
    const TrafficEntry rx =
        entryFor(TrafficEntry::Direction::Rx, r, RtuFrame::encodeReadReply(1, 3, {1000}),
                 QStringLiteral("→ 1000"));
    EXPECT_EQ(dbuAt(1).describe(rx, &r), QStringLiteral("→ 1000 (spno2.speed = 1000 r/min)"));
}

TEST(TrafficDescriberTest, WriteShowsTheWrittenValue)
{
    const ModbusRequest r = ModbusRequest::writeSingle(1, 0xCA03, 1500);
    const TrafficEntry tx =
        entryFor(TrafficEntry::Direction::Tx, r, RtuFrame::encodeRequest(r), r.describe());
    EXPECT_TRUE(dbuAt(1).describe(tx, &r).endsWith(QStringLiteral("(spno2.speed = 1500 r/min)")))
        << dbuAt(1).describe(tx, &r).toStdString();
}

TEST(TrafficDescriberTest, LeavesUnknownDrivesAndRawRequestsAlone)
{
    const ModbusRequest r = ModbusRequest::readHolding(2, 0xCA03, 1);
    const TrafficEntry tx =
        entryFor(TrafficEntry::Direction::Tx, r, RtuFrame::encodeRequest(r), r.describe());
    EXPECT_TRUE(dbuAt(1).describe(tx, &r).isEmpty());
    const ModbusRequest raw = ModbusRequest::rawRequest(1, 0x41, QByteArray("\x01", 1));
    EXPECT_TRUE(dbuAt(1).describe(tx, &raw).isEmpty());
    EXPECT_TRUE(dbuAt(1).describe(tx, nullptr).isEmpty());
}

TEST(TrafficDescriberTest, ErrorsGetTheNameWithoutAValue)
{
    const ModbusRequest r = ModbusRequest::readHolding(1, 0xCA03, 1);
    TrafficEntry event = entryFor(TrafficEntry::Direction::Event, r, {}, QString());
    event.error = QStringLiteral("timeout (no reply)");
    EXPECT_EQ(dbuAt(1).describe(event, &r), QStringLiteral("(spno2.speed)"));
    TrafficEntry exception = entryFor(TrafficEntry::Direction::Rx, r,
                                      RtuFrame::encodeException(1, 3, 2), QStringLiteral("x"));
    exception.function = 0x83;
    EXPECT_EQ(dbuAt(1).describe(exception, &r), QStringLiteral("x (spno2.speed)"));
}

class TrafficDescriberSimTest : public DriveSimFixture
{
};

TEST_F(TrafficDescriberSimTest, DescribesFramesOnTheSimulatedBus)
{
    startBus(QStringLiteral("dbu200@1"));
    log.setDescriber(dbuAt(1).describer());
    control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("1000")});
    const ModbusResult result = await<ModbusResult>([this](auto done) {
        client->submit(ModbusRequest::readHolding(1, 0xCA03, 1), nullptr, done);
    });
    ASSERT_TRUE(result.ok());
    const QVector<TrafficEntry> entries = log.entries();
    ASSERT_EQ(entries.size(), 2);
    EXPECT_TRUE(entries[0].summary.endsWith(QStringLiteral("(spno2.speed)")))
        << entries[0].summary.toStdString();
    EXPECT_EQ(entries[1].summary, QStringLiteral("→ 1000 (spno2.speed = 1000 r/min)"));
}

TEST(TrafficDescriberTest, AWriteToAGroupParentNamesItsChildrenAndABroadcastSaysSo)
{
    TrafficDescriber describer = dbuAt(1);
    BusGroups groups;
    groups.setGroupRaw(1, 0xFFFF);
    groups.setGroupRaw(3, 1);
    groups.setGroupRaw(5, 1);
    describer.setGroups(groups);
    const ModbusRequest w = ModbusRequest::writeSingle(1, 0xCA03, 1500);
    const TrafficEntry tx =
        entryFor(TrafficEntry::Direction::Tx, w, RtuFrame::encodeRequest(w), w.describe());
    EXPECT_TRUE(describer.describe(tx, &w).endsWith(
        QStringLiteral("(spno2.speed = 1500 r/min) — to 1 (group parent: also 3, 5)")))
        << describer.describe(tx, &w).toStdString();
    // A write to a child reaches the child only; reads reach nobody else.
    const ModbusRequest toChild = ModbusRequest::writeSingle(3, 0xCA03, 1500);
    EXPECT_FALSE(describer
                     .describe(entryFor(TrafficEntry::Direction::Tx, toChild,
                                        RtuFrame::encodeRequest(toChild), toChild.describe()),
                               &toChild)
                     .contains(QStringLiteral("group")));
    const ModbusRequest read = ModbusRequest::readHolding(1, 0xCA03, 1);
    EXPECT_FALSE(describer
                     .describe(entryFor(TrafficEntry::Direction::Tx, read,
                                        RtuFrame::encodeRequest(read), read.describe()),
                               &read)
                     .contains(QStringLiteral("group")));
    const ModbusRequest all = ModbusRequest::writeSingle(0, 0x0100, 0);
    EXPECT_TRUE(describer
                    .describe(entryFor(TrafficEntry::Direction::Tx, all,
                                       RtuFrame::encodeRequest(all), all.describe()),
                              &all)
                    .endsWith(QStringLiteral("broadcast: every drive executes it")));
}
