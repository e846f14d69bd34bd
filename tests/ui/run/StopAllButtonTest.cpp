#include "ui/run/StopAllButton.h"
#include "model/bus/BusDrives.h"
#include "model/run/RunControl.h"
#include "tests/ui/UiSimFixture.h"

#include <QApplication>
#include <QMessageBox>
#include <QTest>
#include <QVBoxLayout>

using namespace opentop;

namespace {

class StopAllButtonTest : public test::UiSimFixture
{
protected:
    void TearDown() override
    {
        window.reset();
        busDrives.reset();
        DriveSimFixture::TearDown();
    }
    void runDrive(int slave, const QStringList& words)
    {
        QString error;
        const auto command = RunControl::parse(words, &error);
        ASSERT_TRUE(command) << qPrintable(error);
        RunControl control(client.get(), ProfileRegistry::builtIn());
        const RunControl::Outcome o = await<RunControl::Outcome>(
            [&](auto done) { control.execute(session(slave), *command, done); });
        ASSERT_TRUE(o.ok) << qPrintable(o.error);
    }
    double speed(int slave)
    {
        return await<DeviceSession::Outcome>([&](auto done) {
                   session(slave)->read(QStringLiteral("status.current_speed"), done);
               })
            .value.number;
    }

    std::unique_ptr<BusDrives> busDrives;
    std::unique_ptr<QWidget> window;
};

} // namespace

TEST_F(StopAllButtonTest, StopsEveryDriveAndReportsTheOneThatIgnoresStop)
{
    startBus(QStringLiteral("dbu200@1,dbu400@2"));
    busDrives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
    for (int id : {1, 2}) {
        communicationPriority(id);
        DeviceInfo info;
        info.slave = id;
        info.state = DeviceInfo::State::Present;
        info.family = QStringLiteral("dbu");
        busDrives->update(info);
        runDrive(id, {QStringLiteral("start")});
    }
    control(2, {QStringLiteral("ignore-stop"), QStringLiteral("on")});
    ASSERT_TRUE(waitUntil([&] { return speed(1) > 0 && speed(2) > 0; }));

    window = std::make_unique<QWidget>();
    auto* button = new StopAllButton(busDrives.get(), window.get());
    (new QVBoxLayout(window.get()))->addWidget(button);
    StopAllButton::install(window.get());
    window->show();
    EXPECT_EQ(button->focusPolicy(), Qt::StrongFocus);

    // The keyboard shortcut presses it; no confirmation is asked.
    StopReport report;
    bool finished = false;
    QObject::connect(button, &StopAllButton::finished, button, [&](const StopReport& r) {
        report = r;
        finished = true;
    });
    QTest::keyClick(window.get(), Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
    QCoreApplication::processEvents();
    EXPECT_EQ(QApplication::activeModalWidget(), nullptr);
    EXPECT_TRUE(button->isStopping());
    ASSERT_TRUE(waitUntil([&] { return finished; }, 20000));

    EXPECT_TRUE(report.broadcastOk());
    ASSERT_EQ(report.drives.size(), 2);
    EXPECT_EQ(report.drives[0].state, StopResult::State::Stopped);
    EXPECT_EQ(report.drives[1].state, StopResult::State::StillRunning);
    EXPECT_EQ(speed(1), 0);
    EXPECT_GT(speed(2), 0);
    EXPECT_TRUE(button->reportText().contains(QStringLiteral("Machine number 2: STILL RUNNING")))
        << qPrintable(button->reportText());
    EXPECT_TRUE(button->reportText().contains(QStringLiteral("Machine number 1: stopped")))
        << qPrintable(button->reportText());
    ASSERT_TRUE(button->resultWindow());
    EXPECT_TRUE(button->resultWindow()->isVisible());
    EXPECT_FALSE(button->resultWindow()->isModal());
    EXPECT_EQ(QApplication::activeModalWidget(), nullptr);
    EXPECT_FALSE(button->isStopping());

    // A drive that does not answer is reported too.
    control(2, {QStringLiteral("ignore-stop"), QStringLiteral("off")});
    DeviceInfo ghost;
    ghost.slave = 9;
    ghost.state = DeviceInfo::State::Present;
    ghost.family = QStringLiteral("dbu");
    busDrives->update(ghost);
    finished = false;
    button->click();
    ASSERT_TRUE(waitUntil([&] { return finished; }, 20000));
    ASSERT_EQ(report.drives.size(), 3);
    EXPECT_EQ(report.drives[1].state, StopResult::State::Stopped);
    EXPECT_EQ(report.drives[2].state, StopResult::State::NoAnswer);
    EXPECT_TRUE(button->reportText().contains(QStringLiteral("Machine number 9: NO ANSWER")))
        << qPrintable(button->reportText());
    EXPECT_EQ(button->reportTitle(),
              QStringLiteral("STOP ALL: not every drive is confirmed stopped"));

    // No drive known: the stop is sent, and the title does not claim that any drive stopped.
    for (int id : {1, 2, 9})
        busDrives->remove(id);
    finished = false;
    button->click();
    ASSERT_TRUE(waitUntil([&] { return finished; }, 20000));
    EXPECT_TRUE(report.drives.isEmpty());
    EXPECT_EQ(button->reportTitle(), QStringLiteral("STOP ALL: stop sent, no drive checked"));
    EXPECT_TRUE(button->reportText().contains(QStringLiteral("none was checked")));
}
