// Issue 15: the connection dialog's RS-485 direction and low-latency choices reach the serial
// port the window opens, and the status bar says what the driver accepted. A pty takes neither
// the kernel's RS-485 mode nor RTS, and is no UART.
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/connection/ConnectionDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QRadioButton>
#include <QSpinBox>
#include <pty.h>
#include <unistd.h>

using namespace opentop;
using namespace opentop::test;

namespace {

class MainWindowSerialLineTest : public MainWindowFixture
{
protected:
    void SetUp() override
    {
        char name[256] = {};
        ASSERT_EQ(::openpty(&master, &slave, name, nullptr, nullptr), 0);
        ptyPath = QString::fromLocal8Bit(name);
        MainWindowFixture::SetUp();
    }
    ~MainWindowSerialLineTest() override
    {
        // After TearDown: the window has closed the port by then.
        ::close(master);
        ::close(slave);
    }

    int master = -1;
    int slave = -1;
    QString ptyPath;
};

QAction* connectAction(MainWindow* window)
{
    for (QAction* a : window->findChildren<QAction*>())
        if (a->text() == QStringLiteral("&Connect…"))
            return a;
    return nullptr;
}

// Opens Bus ▸ Connect…, lets `fill` act on the dialog as the user would, then presses Connect.
void throughTheDialog(MainWindow* window, const std::function<void(ConnectionDialog*)>& fill)
{
    QAction* action = connectAction(window);
    ASSERT_NE(action, nullptr);
    bool seen = false;
    QTimer poll;
    poll.setInterval(20);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        auto* dialog = qobject_cast<ConnectionDialog*>(QApplication::activeModalWidget());
        if (!dialog || !dialog->isVisible())
            return;
        poll.stop();
        seen = true;
        fill(dialog);
        dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
        if (dialog->isVisible()) { // refused: say why, and leave
            ADD_FAILURE() << qPrintable(dialog->errorText());
            dialog->reject();
        }
    });
    poll.start();
    action->trigger();
    EXPECT_TRUE(seen);
}

} // namespace

TEST_F(MainWindowSerialLineTest, TheDialogsRs485ChoiceReachesThePortAndTheStatusSaysWhatWasTaken)
{
    ASSERT_TRUE(waitFor([&] { return window->isConnected(); }));
    throughTheDialog(window.get(), [&](ConnectionDialog* dialog) {
        dialog->findChildren<QRadioButton*>().first()->click(); // Serial port
        dialog->findChild<QComboBox*>(QStringLiteral("port"))->setEditText(ptyPath);
        auto* direction = dialog->findChild<QComboBox*>(QStringLiteral("rs485"));
        auto* polarity = dialog->findChild<QComboBox*>(QStringLiteral("rtsPolarity"));
        auto* delay = dialog->findChild<QSpinBox*>(QStringLiteral("rtsDelay"));
        ASSERT_TRUE(direction && polarity && delay);
        // Level and delay apply only where something switches the direction.
        direction->setCurrentIndex(direction->findData(int(ConnectionSettings::Rs485::Off)));
        EXPECT_FALSE(polarity->isEnabled());
        EXPECT_FALSE(delay->isEnabled());
        direction->setCurrentIndex(direction->findData(int(ConnectionSettings::Rs485::Kernel)));
        EXPECT_TRUE(polarity->isEnabled());
        EXPECT_TRUE(delay->isEnabled());
        polarity->setCurrentIndex(polarity->findData(false));
        delay->setValue(1000);
        EXPECT_TRUE(dialog->findChild<QCheckBox*>(QStringLiteral("lowLatency"))->isChecked());
    });
    ASSERT_TRUE(waitFor([&] {
        return window->isConnected() && window->client() &&
               window->client()->settings().port == ptyPath;
    }));
    const ConnectionSettings used = window->client()->settings();
    EXPECT_EQ(used.rs485, ConnectionSettings::Rs485::Kernel);
    EXPECT_FALSE(used.rtsHighWhileSending);
    EXPECT_EQ(used.rtsDelayUs, 1000);
    EXPECT_TRUE(used.lowLatency);

    // The status bar: what the driver took, in red because the mode asked for is not there.
    QLabel* label = window->connectionLabel();
    const QString all = label->toolTip();
    EXPECT_TRUE(all.startsWith(QStringLiteral("Connected: ") + ptyPath)) << qPrintable(all);
    EXPECT_TRUE(all.contains(QStringLiteral("RS-485: kernel mode refused by the driver (")))
        << qPrintable(all);
    EXPECT_TRUE(all.contains(QStringLiteral("low latency: not a UART, no adapter latency")))
        << qPrintable(all);
    EXPECT_TRUE(label->styleSheet().contains(QStringLiteral("#b01c1c")))
        << qPrintable(label->styleSheet());
    EXPECT_LE(label->fontMetrics().horizontalAdvance(label->text()), 530); // shortened, not wider

    // Remembered for the next time, and shown so.
    EXPECT_EQ(ConnectionDialog::remembered().rs485, ConnectionSettings::Rs485::Kernel);
    throughTheDialog(window.get(), [&](ConnectionDialog* dialog) {
        EXPECT_EQ(dialog->settings().rs485, ConnectionSettings::Rs485::Kernel);
        EXPECT_FALSE(dialog->settings().rtsHighWhileSending);
        EXPECT_EQ(dialog->settings().rtsDelayUs, 1000);
        // Back to the adapter switching itself: no longer red.
        auto* direction = dialog->findChild<QComboBox*>(QStringLiteral("rs485"));
        direction->setCurrentIndex(direction->findData(int(ConnectionSettings::Rs485::Off)));
    });
    ASSERT_TRUE(waitFor([&] {
        return window->isConnected() && window->client() &&
               window->client()->settings().rs485 == ConnectionSettings::Rs485::Off;
    }));
    EXPECT_TRUE(label->toolTip().contains(QStringLiteral("RS-485: switched by the adapter; low "
                                                         "latency: not a UART")))
        << qPrintable(label->toolTip());
    EXPECT_FALSE(label->styleSheet().contains(QStringLiteral("#b01c1c")));
}
