#include "ui/traffic/TrafficLogView.h"

#include "model/bus/BusDrives.h"
#include "model/traffic/TrafficDescriber.h"
#include "tests/support/FifoReader.h"
#include "tests/ui/UiSimFixture.h"
#include "ui/traffic/TrafficLogFilter.h"
#include "ui/traffic/TrafficLogModel.h"

#include <QCheckBox>
#include <QFile>
#include <QPushButton>
#include <QTabWidget>
#include <QTemporaryDir>

using namespace opentop;

namespace {

class TrafficLogViewTest : public test::UiSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1"));
        drives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
        DeviceInfo info;
        info.slave = 1;
        info.state = DeviceInfo::State::Present;
        info.family = QStringLiteral("dbu");
        drives->update(info);
        log.setDescriber(TrafficDescriber(drives.get(), ProfileRegistry::builtIn()).describer());
        view = std::make_unique<TrafficLogView>(&log);
    }
    void TearDown() override
    {
        view.reset();
        log.setDescriber({});
        drives.reset();
        DriveSimFixture::TearDown();
    }

    ModbusResult read(int slave)
    {
        return await<ModbusResult>([this, slave](auto done) {
            client->submit(ModbusRequest::readHolding(quint8(slave), 0xCA03, 1), nullptr, done);
        });
    }
    QString shown(int row, int column) const
    {
        return view->filter()->index(row, column).data().toString();
    }
    bool rowsReach(int n)
    {
        return waitUntil([this, n] { return view->model()->rowCount() >= n; });
    }

    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<TrafficLogView> view;
};

} // namespace

TEST_F(TrafficLogViewTest, RealReadAppearsDecodedWithTheParameterName)
{
    control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("1000")});
    ASSERT_TRUE(read(1).ok());
    ASSERT_TRUE(rowsReach(2));
    EXPECT_EQ(shown(0, TrafficLogModel::Direction), QStringLiteral("Tx"));
    EXPECT_EQ(shown(0, TrafficLogModel::Slave), QStringLiteral("1"));
    EXPECT_EQ(shown(0, TrafficLogModel::Function), QStringLiteral("03"));
    EXPECT_EQ(shown(0, TrafficLogModel::Bytes), QStringLiteral("01 03 CA 03 00 01 4B D2"));
    EXPECT_TRUE(shown(0, TrafficLogModel::Meaning).contains(QStringLiteral("(spno2.speed)")));
    EXPECT_EQ(shown(1, TrafficLogModel::Direction), QStringLiteral("Rx"));
    EXPECT_TRUE(shown(1, TrafficLogModel::Meaning)
                    .startsWith(QStringLiteral("→ 1000 (spno2.speed = 1000 r/min)")))
        << shown(1, TrafficLogModel::Meaning).toStdString();
    EXPECT_TRUE(shown(1, TrafficLogModel::Error).isEmpty());
    EXPECT_EQ(view->statistics().drive(1).replies, 1);
}

TEST_F(TrafficLogViewTest, ErrorsOnlyShowsTheTimeoutToAnAbsentDrive)
{
    ASSERT_TRUE(read(1).ok());
    EXPECT_EQ(read(9).error, ModbusError::Timeout);
    ASSERT_TRUE(rowsReach(4));
    auto* errorsOnly = view->findChild<QCheckBox*>(QStringLiteral("trafficErrorsOnly"));
    ASSERT_TRUE(errorsOnly);
    errorsOnly->setChecked(true);
    ASSERT_EQ(view->filter()->rowCount(), 1);
    EXPECT_EQ(shown(0, TrafficLogModel::Slave), QStringLiteral("9"));
    EXPECT_FALSE(shown(0, TrafficLogModel::Error).isEmpty());
    EXPECT_TRUE(
        view->filter()->index(0, TrafficLogModel::Error).data(Qt::BackgroundRole).isValid());
    EXPECT_EQ(view->statistics().drive(9).timeouts, 1);
    errorsOnly->setChecked(false);
    EXPECT_EQ(view->filter()->rowCount(), 4);
}

TEST_F(TrafficLogViewTest, PauseStopsFollowingAndResumeCatchesUp)
{
    ASSERT_TRUE(read(1).ok());
    ASSERT_TRUE(rowsReach(2));
    auto* pause = view->findChild<QPushButton*>(QStringLiteral("trafficPause"));
    ASSERT_TRUE(pause);
    pause->click();
    EXPECT_TRUE(view->isPaused());
    ASSERT_TRUE(read(1).ok());
    ASSERT_TRUE(read(1).ok());
    QCoreApplication::processEvents();
    EXPECT_EQ(log.entries().size(), 6);
    EXPECT_EQ(view->model()->rowCount(), 2);
    pause->click();
    EXPECT_FALSE(view->isPaused());
    EXPECT_EQ(view->model()->rowCount(), 6);
    QCoreApplication::processEvents(); // queued duplicates are dropped
    EXPECT_EQ(view->model()->rowCount(), 6);
    EXPECT_EQ(view->statistics().drive(1).requests, 3);
}

TEST_F(TrafficLogViewTest, SaveWritesOneLinePerFrame)
{
    ASSERT_TRUE(read(1).ok());
    ASSERT_TRUE(rowsReach(2));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("traffic.txt"));
    QString error;
    ASSERT_TRUE(view->saveTo(path, &error)) << error.toStdString();
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines =
        QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 2);
    EXPECT_EQ(lines[0], view->model()->entry(0).toLine());
    EXPECT_EQ(lines[1], view->model()->entry(1).toLine());
    EXPECT_TRUE(lines[1].contains(QStringLiteral("spno2.speed =")));

    view->clear();
    EXPECT_EQ(view->model()->rowCount(), 0);
    EXPECT_TRUE(view->statistics().slaves().isEmpty());
}

TEST_F(TrafficLogViewTest, KeepsAtMostTheLogCapacity)
{
    TrafficLog small(3);
    TrafficLogView smallView(&small);
    for (int i = 0; i < 5; ++i) {
        TrafficEntry e;
        e.slave = quint8(i + 1);
        small.append(e);
    }
    // The view takes new frames from the log a few times a second: those the log no longer
    // held by then (it keeps 3) are neither shown nor counted. With the program's 20,000
    // that takes a GUI stalled for many seconds.
    ASSERT_TRUE(waitUntil([&] { return smallView.statistics().total().requests == 3; }));
    // Rows arrive in batches within the refresh interval.
    ASSERT_TRUE(waitUntil([&] { return smallView.model()->rowCount() == 3; }));
    EXPECT_EQ(smallView.model()->entry(0).slave, 3);
    // Frames after that are all taken, and the rows stay at the log's capacity.
    for (int i = 0; i < 2; ++i) {
        TrafficEntry e;
        e.slave = quint8(10 + i);
        small.append(e);
    }
    ASSERT_TRUE(waitUntil([&] { return smallView.statistics().total().requests == 5; }));
    ASSERT_TRUE(waitUntil([&] { return smallView.model()->entry(2).slave == 11; }));
    EXPECT_EQ(smallView.model()->rowCount(), 3);
}

TEST_F(TrafficLogViewTest, OutOfViewTheRowsComeFromTheLogWhenSeenAgain)
{
    // The program's traffic dock is usually closed or behind another tab: the view then keeps
    // no copy of the frames (the log holds them) and shows the log's last ones when seen.
    TrafficLog small(50);
    QTabWidget window;
    window.addTab(new QWidget, QStringLiteral("other"));
    auto* tabView = new TrafficLogView(&small);
    window.addTab(tabView, QStringLiteral("traffic"));
    window.show();
    ASSERT_FALSE(tabView->isVisible());
    auto append = [&small](int first, int count) {
        for (int i = first; i < first + count; ++i) {
            TrafficEntry e;
            e.slave = quint8(i);
            small.append(e);
        }
    };
    for (int batch = 0; batch < 12; ++batch) {
        append(1 + 10 * batch, 10);
        ASSERT_TRUE(
            waitUntil([&] { return tabView->statistics().total().requests == 10 * (batch + 1); }));
    }
    EXPECT_EQ(tabView->model()->rowCount(), 0);
    window.setCurrentIndex(1);
    ASSERT_TRUE(tabView->isVisible());
    ASSERT_EQ(tabView->model()->rowCount(), 50);
    for (int row = 0; row < 50; ++row)
        EXPECT_EQ(tabView->model()->entry(row).slave, 71 + row) << row;

    // Cleared out of view: frames from before the clear do not come back.
    window.setCurrentIndex(0);
    append(200, 5);
    ASSERT_TRUE(waitUntil([&] { return tabView->statistics().total().requests == 125; }));
    tabView->clear();
    append(210, 3);
    ASSERT_TRUE(waitUntil([&] { return tabView->statistics().total().requests == 3; }));
    window.setCurrentIndex(1);
    ASSERT_EQ(tabView->model()->rowCount(), 3);
    EXPECT_EQ(tabView->model()->entry(0).slave, 210);
    EXPECT_EQ(tabView->model()->entry(2).slave, 212);
    // In view again, new frames are rows as they come.
    append(220, 2);
    ASSERT_TRUE(waitUntil([&] { return tabView->model()->rowCount() == 5; }));
    EXPECT_EQ(tabView->model()->entry(4).slave, 221);
}

TEST_F(TrafficLogViewTest, SaveToAFifoWritesThroughAndAFailedSaveIsAnError)
{
    ASSERT_TRUE(read(1).ok());
    ASSERT_TRUE(rowsReach(2));
    QTemporaryDir dir;
    bool ok = false;
    QString error;
    bool stillFifo = false;
    const QByteArray got = test::saveThroughFifo(
        dir.path(), [&](const QString& path) { ok = view->saveTo(path, &error); }, &stillFifo);
    EXPECT_TRUE(ok) << qPrintable(error);
    EXPECT_TRUE(stillFifo) << "the FIFO was replaced by a regular file";
    EXPECT_EQ(QString::fromUtf8(got).count(QLatin1Char('\n')), 2) << got.constData();

    const QString missing = dir.filePath(QStringLiteral("no-such-folder/traffic.txt"));
    EXPECT_FALSE(view->saveTo(missing, &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("cannot write ") + missing)) << qPrintable(error);
    EXPECT_FALSE(view->saveTo(dir.path(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("it is a directory"))) << qPrintable(error);
}
