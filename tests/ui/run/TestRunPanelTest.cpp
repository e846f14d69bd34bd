#include "ui/run/TestRunPanel.h"
#include "model/bus/BusDrives.h"
#include "model/run/RunControl.h"
#include "tests/ui/UiSimFixture.h"
#include "ui/run/StopAllButton.h"

#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QShortcut>

using namespace opentop;

namespace {

class TestRunPanelTest : public test::UiSimFixture
{
protected:
    void start(const QString& spec, const QVector<QPair<int, QString>>& drives)
    {
        startBus(spec);
        TestRunPanel::forgetConfirmations();
        busDrives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
        for (const auto& d : drives) {
            DeviceInfo info;
            info.slave = d.first;
            info.state = DeviceInfo::State::Present;
            info.family = d.second;
            // As a scan leaves it: the simulated DBU reports no variant, the bus spec names it
            // (no variant question before a start).
            for (const QString& entry : spec.split(QLatin1Char(',')))
                if (entry.endsWith(QStringLiteral("@%1").arg(d.first)) &&
                    entry.startsWith(d.second) && !entry.startsWith(d.second + QLatin1Char('@')))
                    info.variant = entry.section(QLatin1Char('@'), 0, 0);
            busDrives->update(info);
        }
    }
    void TearDown() override
    {
        if (QWidget* modal = QApplication::activeModalWidget())
            modal->close();
        panels.clear();
        busDrives.reset();
        DriveSimFixture::TearDown();
    }

    TestRunPanel* panel(int slave)
    {
        auto p = std::make_unique<TestRunPanel>(busDrives.get(), slave);
        TestRunPanel* raw = p.get();
        bool refreshed = false;
        QObject::connect(raw, &TestRunPanel::refreshed, raw, [&refreshed] { refreshed = true; });
        raw->show();
        EXPECT_TRUE(waitUntil([&] { return refreshed; }));
        QObject::disconnect(raw, &TestRunPanel::refreshed, raw, nullptr);
        panels.push_back(std::move(p));
        return raw;
    }
    QPushButton* button(QWidget* w, const char* name)
    {
        auto* b = w->findChild<QPushButton*>(QLatin1String(name));
        EXPECT_TRUE(b) << name;
        return b;
    }
    QMessageBox* waitForBox()
    {
        QMessageBox* box = nullptr;
        waitUntil([&] {
            box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            return box != nullptr;
        });
        return box;
    }
    // Clicks `name` and waits for the command to finish, answering a confirmation if asked.
    bool command(TestRunPanel* p, const char* name, bool* asked = nullptr)
    {
        bool finished = false;
        bool ok = false;
        const auto c = QObject::connect(p, &TestRunPanel::commandFinished, p, [&](bool o) {
            finished = true;
            ok = o;
        });
        button(p, name)->click();
        QCoreApplication::processEvents();
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (asked)
            *asked = box != nullptr;
        if (box)
            box->button(QMessageBox::Yes)->click();
        EXPECT_TRUE(waitUntil([&] { return finished; }, 10000)) << name;
        QObject::disconnect(c);
        return ok;
    }
    double read(int slave, const QString& name)
    {
        return await<DeviceSession::Outcome>([&](auto done) { session(slave)->read(name, done); })
            .value.number;
    }

    std::unique_ptr<BusDrives> busDrives;
    std::vector<std::unique_ptr<TestRunPanel>> panels;
};

} // namespace

TEST_F(TestRunPanelTest, IoPriorityIsRefusedWithItsExplanationAndNothingSent)
{
    start(QStringLiteral("dbu200@1"), {{1, QStringLiteral("dbu")}});
    TestRunPanel* p = panel(1);
    EXPECT_FALSE(p->commandsEnabled());
    EXPECT_TRUE(p->priorityExplanation().contains(QStringLiteral("input terminals")))
        << qPrintable(p->priorityExplanation());
    EXPECT_TRUE(p->priorityExplanation().contains(QStringLiteral("Communication priority")))
        << qPrintable(p->priorityExplanation());
    EXPECT_FALSE(button(p, "start")->isEnabled());
    button(p, "start")->click();
    QCoreApplication::processEvents();
    EXPECT_EQ(QApplication::activeModalWidget(), nullptr);
    EXPECT_EQ(writesSent(), 0);

    // Switching asks first; cancelling sends nothing, confirming sets communication priority.
    button(p, "switchPriority")->click();
    QMessageBox* box = waitForBox();
    ASSERT_TRUE(box);
    box->button(QMessageBox::Cancel)->click();
    QCoreApplication::processEvents();
    EXPECT_EQ(writesSent(), 0);
    ASSERT_TRUE(runUntil(p, &TestRunPanel::refreshed, [&] {
        button(p, "switchPriority")->click();
        QMessageBox* again = waitForBox();
        ASSERT_TRUE(again);
        again->button(QMessageBox::Yes)->click();
    }));
    EXPECT_EQ(simRegister(1, 0x100D), 2);
    EXPECT_TRUE(p->commandsEnabled());
    EXPECT_TRUE(p->priorityExplanation().isEmpty());
    EXPECT_TRUE(button(p, "start")->isEnabled());
}

TEST_F(TestRunPanelTest, AsksOncePerDriveBeforeTheFirstStartAndSelectsAnSpno)
{
    start(QStringLiteral("dbu200@1,dbu200@2"),
          {{1, QStringLiteral("dbu")}, {2, QStringLiteral("dbu")}});
    communicationPriority(1);
    communicationPriority(2);
    TestRunPanel* p = panel(1);
    ASSERT_TRUE(p->commandsEnabled());

    auto* spno = p->findChild<QComboBox*>(QStringLiteral("spno"));
    ASSERT_TRUE(spno);
    EXPECT_EQ(spno->count(), 8);
    spno->setCurrentIndex(2);
    bool asked = true;
    EXPECT_TRUE(command(p, "select", &asked));
    EXPECT_FALSE(asked);
    EXPECT_TRUE(p->stateText().contains(QStringLiteral("SPno3"))) << qPrintable(p->stateText());
    EXPECT_EQ(simRegister(1, 0x200F), 2);

    // The first start asks; nothing is sent until it is answered.
    const int before = writesSent();
    button(p, "start")->click();
    QMessageBox* box = waitForBox();
    ASSERT_TRUE(box);
    EXPECT_EQ(writesSent(), before);
    bool finished = false;
    QObject::connect(p, &TestRunPanel::commandFinished, p, [&] { finished = true; });
    box->button(QMessageBox::Yes)->click();
    ASSERT_TRUE(waitUntil([&] { return finished; }, 10000));
    QObject::disconnect(p, &TestRunPanel::commandFinished, p, nullptr);
    EXPECT_TRUE(TestRunPanel::startConfirmed(1));
    EXPECT_TRUE(p->stateText().contains(QStringLiteral("running"))) << qPrintable(p->stateText());
    EXPECT_TRUE(waitUntil([&] { return read(1, QStringLiteral("status.current_speed")) > 0; }));

    EXPECT_TRUE(command(p, "stop", &asked));
    EXPECT_FALSE(asked);
    EXPECT_TRUE(command(p, "start", &asked));
    EXPECT_FALSE(asked) << "asked a second time for the same drive";
    EXPECT_TRUE(command(p, "stop"));

    // Another drive is asked for again; cancelling sends nothing.
    TestRunPanel* other = panel(2);
    const int beforeOther = writesSent();
    button(other, "start")->click();
    QMessageBox* otherBox = waitForBox();
    ASSERT_TRUE(otherBox);
    otherBox->button(QMessageBox::Cancel)->click();
    QCoreApplication::processEvents();
    EXPECT_EQ(writesSent(), beforeOther);
    EXPECT_FALSE(TestRunPanel::startConfirmed(2));
}

TEST_F(TestRunPanelTest, DcSpeedCommandIsValidatedAsTyped)
{
    start(QStringLiteral("dcpid@7"), {{7, QStringLiteral("dcpid")}});
    TestRunPanel* p = panel(7);
    ASSERT_TRUE(p->commandsEnabled());
    EXPECT_FALSE(p->findChild<QPushButton*>(QStringLiteral("start")));
    auto* speed = p->findChild<QLineEdit*>(QStringLiteral("speed"));
    ASSERT_TRUE(speed);
    speed->setText(QStringLiteral("150"));
    EXPECT_TRUE(p->speedError().contains(QStringLiteral("100.0"))) << qPrintable(p->speedError());
    EXPECT_FALSE(button(p, "setSpeed")->isEnabled());
    speed->setText(QStringLiteral("5x"));
    EXPECT_FALSE(p->speedError().isEmpty());
    EXPECT_FALSE(button(p, "setSpeed")->isEnabled());
    speed->setText(QStringLiteral("50"));
    EXPECT_TRUE(p->speedError().isEmpty()) << qPrintable(p->speedError());
    ASSERT_TRUE(button(p, "setSpeed")->isEnabled());
    EXPECT_EQ(writesSent(), 0);

    bool asked = false;
    EXPECT_TRUE(command(p, "setSpeed", &asked));
    EXPECT_TRUE(asked);
    EXPECT_TRUE(waitUntil([&] { return read(7, QStringLiteral("status.pwm")) == 50; }));
    EXPECT_TRUE(command(p, "brake", &asked));
    EXPECT_FALSE(asked);
    EXPECT_TRUE(waitUntil([&] { return read(7, QStringLiteral("status.pwm")) == 0; }));

    // With a communication loss stop time, paused polling would brake the motor.
    p->setPollingActive(false);
    EXPECT_TRUE(p->pollingWarning().isEmpty());
    control(7, {QStringLiteral("set"), QStringLiteral("0x008E"), QStringLiteral("20")});
    ASSERT_TRUE(runUntil(p, &TestRunPanel::refreshed, [&] { p->refresh(); }));
    EXPECT_TRUE(p->pollingWarning().contains(QStringLiteral("2.0 s")))
        << qPrintable(p->pollingWarning());
    p->setPollingActive(true);
    EXPECT_TRUE(p->pollingWarning().isEmpty());
}
