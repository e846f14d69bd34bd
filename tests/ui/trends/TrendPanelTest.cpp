#include "ui/trends/TrendPanel.h"
#include "tests/ui/trends/TrendFixture.h"
#include "ui/trends/TrendChart.h"

#include <QChart>
#include <QComboBox>
#include <QDir>
#include <QLineSeries>
#include <QPushButton>
#include <QTreeWidget>

using namespace opentop;

namespace {

class TrendPanelTest : public test::TrendFixture
{
protected:
    static QStringList sourceTexts(const TrendPanel& panel)
    {
        QStringList list;
        for (const TrendSource& s : panel.chart()->sources())
            list << QStringLiteral("%1 %2").arg(s.slave).arg(s.key);
        return list;
    }
};

} // namespace

TEST_F(TrendPanelTest, PollRateComboSetsTheHubInterval)
{
    TrendPanel panel(hub.get());
    auto* rate = panel.findChild<QComboBox*>(QStringLiteral("pollRate"));
    ASSERT_TRUE(rate);
    EXPECT_EQ(rate->currentText(), QStringLiteral("20 Hz (50 ms)")); // the fixture's interval
    const int tenHz = rate->findText(QStringLiteral("10 Hz (100 ms)"));
    ASSERT_GE(tenHz, 0);
    rate->setCurrentIndex(tenHz);
    EXPECT_EQ(hub->interval(), 100);
    rate->setCurrentIndex(rate->findText(QStringLiteral("1 Hz (1000 ms)")));
    EXPECT_EQ(hub->interval(), 1000);
    // Another view changing the interval shows here.
    hub->setInterval(200);
    EXPECT_EQ(rate->currentText(), QStringLiteral("5 Hz (200 ms)"));
    hub->setInterval(250);
    EXPECT_EQ(rate->currentText(), QStringLiteral("4 Hz (250 ms)"));
    EXPECT_EQ(hub->interval(), 250);

    auto* window = panel.findChild<QComboBox*>(QStringLiteral("timeWindow"));
    ASSERT_TRUE(window);
    window->setCurrentIndex(window->findText(QStringLiteral("5 min")));
    EXPECT_EQ(panel.chart()->windowSeconds(), 300);
}

TEST_F(TrendPanelTest, ChartsEveryDrivesSpeedOrTheSelectedDrivesAndFollowsTheDriveList)
{
    TrendPanel panel(hub.get());
    EXPECT_EQ(sourceTexts(panel), (QStringList{QStringLiteral("1 status.current_speed"),
                                               QStringLiteral("2 status.current_speed")}));
    EXPECT_EQ(panel.tree()->topLevelItemCount(), 2);
    EXPECT_EQ(panel.tree()->topLevelItem(0)->text(0), QStringLiteral("1 DBU200"));
    EXPECT_EQ(panel.tree()->topLevelItem(0)->child(0)->text(0),
              QStringLiteral("Current speed [r/min]"));

    panel.showDrives({2});
    EXPECT_EQ(sourceTexts(panel), (QStringList{QStringLiteral("2 status.current_speed"),
                                               QStringLiteral("2 status.target_speed"),
                                               QStringLiteral("2 status.load")}));
    ASSERT_TRUE(panel.setChecked(1, QStringLiteral("status.load"), true));
    EXPECT_EQ(sourceTexts(panel).first(), QStringLiteral("1 status.load"));
    EXPECT_FALSE(panel.setChecked(9, QStringLiteral("status.load"), true));

    // A drive found later appears, unchecked (it is not among the selected); a removed one goes.
    DeviceInfo info;
    info.slave = 3;
    info.state = DeviceInfo::State::Present;
    info.family = QStringLiteral("dbu");
    info.variant = QStringLiteral("dbu200");
    info.model = QStringLiteral("DBU200");
    drives->update(info);
    EXPECT_EQ(panel.tree()->topLevelItemCount(), 3);
    EXPECT_EQ(sourceTexts(panel).size(), 4);
    drives->remove(2);
    EXPECT_EQ(panel.tree()->topLevelItemCount(), 2);
    EXPECT_EQ(sourceTexts(panel), QStringList{QStringLiteral("1 status.load")});
}

TEST_F(TrendPanelTest, ButtonsPauseResumeAndGoLive)
{
    TrendPanel panel(hub.get());
    panel.resize(1000, 600);
    panel.show();
    auto* pause = panel.findChild<QPushButton*>(QStringLiteral("pause"));
    auto* live = panel.findChild<QPushButton*>(QStringLiteral("live"));
    ASSERT_TRUE(pause && live);
    EXPECT_FALSE(live->isEnabled());
    pause->click();
    EXPECT_TRUE(panel.chart()->isPaused());
    EXPECT_EQ(pause->text(), QStringLiteral("Resume"));
    EXPECT_TRUE(live->isEnabled());
    live->click();
    EXPECT_FALSE(panel.chart()->isPaused());
    EXPECT_EQ(pause->text(), QStringLiteral("Pause"));
    EXPECT_FALSE(pause->isChecked());
    EXPECT_FALSE(live->isEnabled());
}
