// Comparing parameter sets: by name, with each side's units and meaning, and against the
// profile's factory defaults, where a parameter without a documented default is listed and
// never counted as a difference.
#include "model/files/Comparer.h"
#include "tests/model/files/BackupTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class ComparerTest : public SimBusFixture
{
protected:
    BackupDevice read(int slave)
    {
        const BackupReader::Result r = backup(slave);
        EXPECT_TRUE(r.ok) << qPrintable(r.failures.join(QLatin1Char('\n')));
        return r.device;
    }

    static void change(BackupDevice* device, const char* name, QVector<quint16> registers)
    {
        for (BackupParameter& p : device->parameters) {
            if (p.name == QLatin1String(name))
                p.registers = registers;
        }
    }
};

} // namespace

TEST_F(ComparerTest, IdenticalSetsHaveNoDifferences)
{
    const BackupDevice a = read(1);
    const Comparer::Result r = Comparer::compare(profile("dbu"), a, a);
    EXPECT_TRUE(r.refusal.isEmpty());
    EXPECT_TRUE(r.differences.isEmpty());
    EXPECT_EQ(r.compared, a.parameters.size());
}

TEST_F(ComparerTest, FileAgainstDriveShowsValuesWithUnits)
{
    const BackupDevice file = read(1);
    set(1, 0xCA03, 1500);
    set(1, 0x1305, 25);
    const BackupDevice drive = read(1);
    const Comparer::Result r = Comparer::compare(profile("dbu"), file, drive);
    ASSERT_EQ(r.differences.size(), 2);
    // Profile order: SPno2 speed before SPno3 acceleration.
    EXPECT_EQ(r.differences.at(0).parameter, QStringLiteral("spno2.speed"));
    EXPECT_EQ(r.differences.at(0).a, QStringLiteral("1000 r/min"));
    EXPECT_EQ(r.differences.at(0).b, QStringLiteral("1500 r/min"));
    EXPECT_EQ(r.differences.at(0).bRegisters, (QVector<quint16>{1500}));
    EXPECT_EQ(r.differences.at(1).parameter, QStringLiteral("spno3.accel"));
    EXPECT_EQ(r.differences.at(1).a, QStringLiteral("0.5 s"));
    EXPECT_EQ(r.differences.at(1).b, QStringLiteral("2.5 s"));
}

TEST_F(ComparerTest, DriveAgainstDriveNotesDifferentVariants)
{
    const Comparer::Result r = Comparer::compare(profile("dbu"), read(1), read(150));
    EXPECT_TRUE(r.differences.isEmpty()); // both at their factory settings
    EXPECT_EQ(r.notes, QStringList{QStringLiteral("the variants differ: dbu200 and dbu400")});
}

TEST_F(ComparerTest, EachSideIsShownInItsOwnControlMode)
{
    const BackupDevice mode2 = read(1);
    BackupDevice mode1 = mode2;
    change(&mode1, "core.control_mode", {0});
    change(&mode1, "io.x0", {1});
    const Comparer::Result r = Comparer::compare(profile("dbu"), mode1, mode2);
    ASSERT_EQ(r.differences.size(), 2);
    EXPECT_EQ(r.differences.at(1).parameter, QStringLiteral("io.x0"));
    EXPECT_EQ(r.differences.at(1).a, QStringLiteral("RUN/STOP"));
    EXPECT_EQ(r.differences.at(1).b, QStringLiteral("CW/STOP"));
}

TEST_F(ComparerTest, RefusesDifferentFamilies)
{
    const Comparer::Result r = Comparer::compare(profile("dbu"), read(1), read(7));
    EXPECT_TRUE(r.refusal.contains(QStringLiteral("nothing to compare"))) << qPrintable(r.refusal);
    EXPECT_TRUE(r.differences.isEmpty());
}

TEST_F(ComparerTest, ParametersOnlyOneSideHoldsAreDifferences)
{
    const BackupDevice full = read(1);
    BackupDevice older = full;
    older.parameters.removeLast();
    const Comparer::Result r = Comparer::compare(profile("dbu"), older, full);
    ASSERT_EQ(r.differences.size(), 1);
    EXPECT_TRUE(r.differences.first().a.isEmpty());
    EXPECT_FALSE(r.differences.first().b.isEmpty());
    EXPECT_EQ(r.compared, full.parameters.size() - 1);
}

TEST_F(ComparerTest, FactoryDefaultsFollowTheDefaultControlMode)
{
    QStringList undocumented;
    const BackupDevice defaults =
        Comparer::factoryDefaults(profile("dbu"), QStringLiteral("dbu400"), &undocumented);
    EXPECT_EQ(defaults.text(profile("dbu"), QStringLiteral("io.x0")), QStringLiteral("CW/STOP"));
    EXPECT_EQ(defaults.text(profile("dbu"), QStringLiteral("io.y0")), QStringLiteral("Speed-Out"));
    EXPECT_EQ(defaults.text(profile("dbu"), QStringLiteral("spno2.speed")),
              QStringLiteral("1000 r/min"));
    EXPECT_TRUE(undocumented.contains(QStringLiteral("va.countdown_days")));
    EXPECT_FALSE(defaults.parameter(QStringLiteral("va.countdown_days")));
}

TEST_F(ComparerTest, AgainstFactoryDefaultsUndocumentedDefaultsAreNeverDifferences)
{
    // The simulated DBU starts at the profile's defaults.
    const BackupDevice drive = read(1);
    Comparer::Result r = Comparer::compareWithDefaults(profile("dbu"), drive);
    EXPECT_TRUE(r.differences.isEmpty());
    EXPECT_TRUE(r.noDefault.contains(QStringLiteral("va.countdown_days")));
    EXPECT_EQ(r.compared + r.noDefault.size(), drive.parameters.size());

    BackupDevice changed = drive;
    change(&changed, "va.countdown_days", {12}); // no documented default: still no difference
    change(&changed, "spno2.speed", {1200});
    r = Comparer::compareWithDefaults(profile("dbu"), changed);
    ASSERT_EQ(r.differences.size(), 1);
    EXPECT_EQ(r.differences.first().parameter, QStringLiteral("spno2.speed"));
    EXPECT_EQ(r.differences.first().a, QStringLiteral("1200 r/min"));
    EXPECT_EQ(r.differences.first().b, QStringLiteral("1000 r/min"));

    // The DC controller's manual gives almost no defaults: nearly everything is listed.
    const Comparer::Result dc = Comparer::compareWithDefaults(profile("dcpid"), read(7));
    EXPECT_TRUE(dc.differences.isEmpty());
    EXPECT_TRUE(dc.noDefault.contains(QStringLiteral("pid.p")));
    EXPECT_EQ(dc.compared, 2); // config.baud and config.parity
}
