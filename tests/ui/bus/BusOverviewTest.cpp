// The bus overview against the in-process simulated bus: every drive live in one grid while
// it is shown, an alarm marked, nothing polled while it is hidden.
#include "ui/bus/BusOverview.h"
#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "tests/model/DriveSimFixture.h"
#include "ui/bus/BusOverviewModel.h"

#include <QBrush>
#include <QSignalSpy>
#include <QTableView>

using namespace opentop;
using namespace opentop::test;

namespace {

class BusOverviewTest : public DriveSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1,dbu400@2,dcpid@7"));
        drives = identifiedDrives({1, 2, 7});
        hub = std::make_unique<MonitorHub>(drives.get());
        hub->setInterval(50);
        overview = std::make_unique<BusOverview>(drives.get(), hub.get());
    }

    void TearDown() override
    {
        overview.reset();
        hub.reset();
        drives.reset();
        DriveSimFixture::TearDown();
    }

    QString cell(int slave, BusOverviewModel::Column column)
    {
        return overview->model()->text(slave, column);
    }

    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<MonitorHub> hub;
    std::unique_ptr<BusOverview> overview;
};

} // namespace

TEST_F(BusOverviewTest, ShowsEveryDriveLiveWhileShown)
{
    EXPECT_TRUE(hub->watched().isEmpty());
    overview->show();
    EXPECT_EQ(hub->watched(), (QVector<int>{1, 2, 7}));
    EXPECT_EQ(overview->model()->rowCount(), 3);
    control(2, {QStringLiteral("vr"), QStringLiteral("1200")});
    control(2, {QStringLiteral("input"), QStringLiteral("2")}); // CCW
    ASSERT_TRUE(waitUntil(
        [&] { return cell(2, BusOverviewModel::Speed) == QStringLiteral("-1200 r/min"); }, 8000))
        << qPrintable(cell(2, BusOverviewModel::Speed));
    EXPECT_EQ(cell(2, BusOverviewModel::State), QStringLiteral("Running CCW"));
    // The target register holds the magnitude; shown signed like the speed.
    EXPECT_EQ(cell(2, BusOverviewModel::Target), QStringLiteral("-1200 r/min"));
    EXPECT_EQ(cell(1, BusOverviewModel::State), QStringLiteral("Stopped"));
    EXPECT_EQ(cell(1, BusOverviewModel::Speed), QStringLiteral("0 r/min"));
    EXPECT_EQ(cell(1, BusOverviewModel::Load), QStringLiteral("0 %"));
    EXPECT_EQ(cell(1, BusOverviewModel::Alarm), QStringLiteral("none"));
    EXPECT_EQ(cell(1, BusOverviewModel::DisplaySpeed), QStringLiteral("0.000 r/min"));
    // The DC controller: its speed is a commutation frequency.
    EXPECT_EQ(cell(7, BusOverviewModel::Speed), QStringLiteral("0 1/s"));
    EXPECT_EQ(cell(7, BusOverviewModel::Drive), QStringLiteral("7 DCPID"));
}

TEST_F(BusOverviewTest, AnAlarmIsNamedAndMarkedRed)
{
    overview->show();
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    ASSERT_TRUE(waitUntil([&] {
        return cell(1, BusOverviewModel::Alarm).contains(QStringLiteral("AL007"));
    })) << qPrintable(cell(1, BusOverviewModel::Alarm));
    const QModelIndex index =
        overview->model()->index(overview->model()->rowOf(1), BusOverviewModel::Alarm);
    EXPECT_EQ(index.data(Qt::BackgroundRole).value<QBrush>().color(), QColor(0xe5, 0x1c, 0x23));
    EXPECT_EQ(cell(2, BusOverviewModel::Alarm), QStringLiteral("none"));
}

TEST_F(BusOverviewTest, HiddenItPollsNothing)
{
    overview->show();
    ASSERT_TRUE(waitUntil([&] { return hub->statistics(7).samples >= 2; }));
    overview->hide();
    EXPECT_TRUE(hub->watched().isEmpty());
    waitUntil([] { return false; }, 150); // a poll under way finishes
    const int frames = framesSent();
    waitUntil([] { return false; }, 300);
    EXPECT_EQ(framesSent(), frames);
}

TEST_F(BusOverviewTest, ReportsTheCellsThatChangedOnlyOneAtATime)
{
    overview->show();
    ASSERT_TRUE(waitUntil([&] {
        return cell(1, BusOverviewModel::State) == QStringLiteral("Stopped") &&
               cell(7, BusOverviewModel::Speed) == QStringLiteral("0 1/s");
    }));
    // A dozen samples of each drive and a few refreshes: the stopped drives' values stay; at
    // most their ages move on. A view repaints those cells, not the grid.
    QSignalSpy spy(overview->model(), &QAbstractItemModel::dataChanged);
    waitUntil([] { return false; }, 700);
    for (const QList<QVariant>& args : spy) {
        const QModelIndex from = args.at(0).value<QModelIndex>();
        EXPECT_EQ(from, args.at(1).value<QModelIndex>());
        EXPECT_EQ(from.column(), BusOverviewModel::Communication);
    }
}
