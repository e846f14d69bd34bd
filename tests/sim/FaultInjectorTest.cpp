// Fault injection: parsing, reproducibility from a seed, rates, and the effect on the bus.
#include "tests/sim/SimTestSupport.h"

#include "sim/FaultInjector.h"

using namespace opentop;
using namespace opentop::test;

TEST(FaultInjector, ParsesRatesAndRejectsBadInput)
{
    QString error;
    const auto rates =
        FaultInjector::parse(QStringLiteral("drop=0.02,crc=0.01,late=0.01,busy=0.01"), &error);
    ASSERT_TRUE(rates) << error.toStdString();
    EXPECT_DOUBLE_EQ(rates->drop, 0.02);
    EXPECT_DOUBLE_EQ(rates->busy, 0.01);
    EXPECT_EQ(rates->lateMs, 1000);
    EXPECT_EQ(FaultInjector::parse(QStringLiteral("late=0.5,late_ms=1500"), &error)->lateMs, 1500);
    EXPECT_TRUE(FaultInjector::parse(QString(), &error));

    EXPECT_FALSE(FaultInjector::parse(QStringLiteral("lose=0.1"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("drop"))) << error.toStdString();
    EXPECT_FALSE(FaultInjector::parse(QStringLiteral("drop=2"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("0..1"))) << error.toStdString();
    EXPECT_FALSE(FaultInjector::parse(QStringLiteral("drop"), &error));
    EXPECT_FALSE(FaultInjector::parse(QStringLiteral("drop=x"), &error));
    EXPECT_FALSE(FaultInjector::parse(QStringLiteral("drop=0.6,crc=0.6"), &error));
    EXPECT_FALSE(FaultInjector::parse(QStringLiteral("late_ms=0"), &error));
}

TEST(FaultInjector, SameSeedSameFaults)
{
    FaultInjector::Rates rates;
    rates.drop = rates.crc = rates.late = rates.busy = 0.1;
    FaultInjector a(rates, 42);
    FaultInjector b(rates, 42);
    FaultInjector c(rates, 43);
    int differences = 0;
    for (int i = 0; i < 1000; ++i) {
        const FaultInjector::Fault fa = a.next();
        EXPECT_EQ(fa, b.next());
        differences += fa != c.next();
    }
    EXPECT_GT(differences, 100);
}

TEST(FaultInjector, RatesAreRoughlyAsConfigured)
{
    FaultInjector::Rates rates;
    rates.drop = 0.02;
    rates.crc = 0.01;
    rates.late = 0.01;
    rates.busy = 0.05;
    FaultInjector f(rates, 7);
    QHash<int, int> counts;
    const int n = 40000;
    for (int i = 0; i < n; ++i)
        ++counts[int(f.next())];
    EXPECT_NEAR(counts[int(FaultInjector::Fault::Drop)] / double(n), 0.02, 0.004);
    EXPECT_NEAR(counts[int(FaultInjector::Fault::Crc)] / double(n), 0.01, 0.003);
    EXPECT_NEAR(counts[int(FaultInjector::Fault::Late)] / double(n), 0.01, 0.003);
    EXPECT_NEAR(counts[int(FaultInjector::Fault::Busy)] / double(n), 0.05, 0.006);
    EXPECT_EQ(FaultInjector().next(), FaultInjector::Fault::None);
}

namespace {

SimFixture faulty(const char* spec, double FaultInjector::Rates::*which)
{
    SimFixture sim(spec);
    FaultInjector::Rates rates;
    rates.*which = 1.0;
    sim.bus->setFaults(FaultInjector(rates, 1));
    return sim;
}

} // namespace

TEST(FaultInjector, DropLosesTheReplyButTheWriteIsDone)
{
    SimFixture sim = faulty("dbu200@1", &FaultInjector::Rates::drop);
    EXPECT_FALSE(sim.write(1, "spno2.speed", 1234).replied);
    EXPECT_EQ(sim.device(1)->raw(QStringLiteral("spno2.speed")), 1234);
}

TEST(FaultInjector, CrcCorruptsTheReply)
{
    SimFixture sim = faulty("dbu200@1", &FaultInjector::Rates::crc);
    const Answer a = sim.read(1, 3, 0xCA03);
    ASSERT_TRUE(a.replied);
    EXPECT_FALSE(ModbusCrc::check(a.adu));
    EXPECT_EQ(a.adu.left(5), hexBytes("01 03 02 03 E8"));
}

TEST(FaultInjector, LateRepliesCarryTheDelay)
{
    SimFixture sim = faulty("dbu200@1", &FaultInjector::Rates::late);
    const SimOutcome out = sim.bus->handleFrame(hexBytes("01 03 CA 03 00 01 4B D2"), 0);
    EXPECT_EQ(out.delayMs, 1000);
    EXPECT_EQ(out.reply, hexBytes("01 03 02 03 E8 B8 FA"));
    EXPECT_EQ(out.fault, FaultInjector::Fault::Late);
}

TEST(FaultInjector, BusyRefusesWithoutExecuting)
{
    SimFixture dbu = faulty("dbu200@1", &FaultInjector::Rates::busy);
    EXPECT_EQ(dbu.write(1, "spno2.speed", 1234).exception, 0x04);
    EXPECT_EQ(dbu.device(1)->raw(QStringLiteral("spno2.speed")), 1000);
    EXPECT_EQ(dbu.device(1)->raw(QStringLiteral("status.comm_error")), 0xE3);
    SimFixture dc = faulty("dcpid@7", &FaultInjector::Rates::busy);
    EXPECT_EQ(dc.read(7, 3, 0x0010).exception, 0x06);
}

TEST(FaultInjector, BroadcastsAndUnknownIdsDrawNoFault)
{
    SimFixture sim = faulty("dbu200@1", &FaultInjector::Rates::busy);
    EXPECT_FALSE(sim.write(0, 0xCA03, 1500).replied);
    EXPECT_EQ(sim.device(1)->raw(QStringLiteral("spno2.speed")), 1500);
}

TEST(FaultInjector, BusFaultsAreReproducibleAndNearTheRate)
{
    auto pattern = [](quint32 seed) {
        SimFixture sim("dbu200@1");
        FaultInjector::Rates rates;
        rates.drop = 0.1;
        sim.bus->setFaults(FaultInjector(rates, seed));
        QVector<bool> replied;
        for (int i = 0; i < 2000; ++i)
            replied << sim.read(1, 3, 0xCA03).replied;
        return replied;
    };
    const QVector<bool> a = pattern(5);
    EXPECT_EQ(a, pattern(5));
    EXPECT_NE(a, pattern(6));
    EXPECT_NEAR(a.count(false) / 2000.0, 0.1, 0.025);
}
