// The soak's own parts: its options, the opentop program's totals line, /proc figures.
#include "tests/soak/GuiSoak.h"
#include "tests/soak/ProcessProbe.h"
#include "tests/soak/SoakOptions.h"

#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop::soak;

TEST(SoakPartsTest, ReadsTheGuiTotalsLine)
{
    SoakPart::Totals t;
    ASSERT_TRUE(GuiSoak::parseTotals(
        QStringLiteral(
            "monitor: 247 drives, 12345 samples, 7 errors, 2 stale, 5000 trend points, 19998 "
            "of 20000 traffic frames\n"),
        &t));
    EXPECT_EQ(t.drives, 247);
    EXPECT_EQ(t.samples, 12345);
    EXPECT_EQ(t.errors, 7);
    EXPECT_EQ(t.stale, 2);
    EXPECT_EQ(t.trendPoints, 5000);
    EXPECT_EQ(t.trafficFrames, 19998);
    EXPECT_EQ(t.trafficCapacity, 20000);
    EXPECT_FALSE(GuiSoak::parseTotals(QStringLiteral("drive 1: 5 samples, 0 errors"), &t));
}

TEST(SoakPartsTest, OptionsDefaultToAnHourOf247Drives)
{
    QString error;
    bool help = true;
    const auto o = SoakOptions::parse({}, &error, &help);
    ASSERT_TRUE(o);
    EXPECT_FALSE(help);
    EXPECT_DOUBLE_EQ(o->minutes, 60);
    EXPECT_DOUBLE_EQ(o->intervalSeconds, 60);
    EXPECT_TRUE(o->gui && o->model);
    EXPECT_EQ(o->devices, QStringLiteral("dcpid@1-40,dbu200@41-140,dbu400@141-247"));
}

TEST(SoakPartsTest, OptionsRefuseWhatCannotRun)
{
    QString error;
    bool help = false;
    EXPECT_FALSE(
        SoakOptions::parse({QStringLiteral("--minutes"), QStringLiteral("x")}, &error, &help));
    EXPECT_TRUE(error.contains(QStringLiteral("--minutes")));
    EXPECT_FALSE(SoakOptions::parse({QStringLiteral("--no-gui"), QStringLiteral("--no-model")},
                                    &error, &help));
    EXPECT_FALSE(SoakOptions::parse({QStringLiteral("--minutes"), QStringLiteral("1"),
                                     QStringLiteral("--interval-seconds"), QStringLiteral("90")},
                                    &error, &help));
    EXPECT_FALSE(SoakOptions::parse({QStringLiteral("--bogus")}, &error, &help));
    EXPECT_FALSE(SoakOptions::parse({QStringLiteral("--minutes"), QStringLiteral("1"),
                                     QStringLiteral("--warmup-seconds"), QStringLiteral("60")},
                                    &error, &help));
    const auto o = SoakOptions::parse({QStringLiteral("--minutes"), QStringLiteral("2"),
                                       QStringLiteral("--interval-seconds"), QStringLiteral("10"),
                                       QStringLiteral("--no-gui")},
                                      &error, &help);
    ASSERT_TRUE(o);
    EXPECT_DOUBLE_EQ(o->minutes, 2);
    EXPECT_FALSE(o->gui);
}

TEST(SoakPartsTest, ProbeCountsThisProcessesFilesAndThreads)
{
    const ProcessFigures before = ProcessProbe::read();
    ASSERT_TRUE(before.valid());
    EXPECT_GT(before.rssKb, 0);
    EXPECT_GE(before.threads, 1);
    QTemporaryDir dir;
    QFile file(dir.filePath(QStringLiteral("probe")));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    const ProcessFigures opened = ProcessProbe::read();
    EXPECT_EQ(opened.fds, before.fds + 1);
    file.close();
    EXPECT_EQ(ProcessProbe::read().fds, before.fds);
    EXPECT_FALSE(ProcessProbe::read(999999999).valid()); // no such process
}
