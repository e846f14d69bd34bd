// Drives of different line formats on one bus, through the whole window: a DC controller at
// its own 8E1 on a DBU bus at 19200 8N1 is not found by a scan (which says why), is added by
// hand with its format, and then both drives are live; the bus list shows the format, its
// context menu changes it, and the bus is remembered with it.
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/bus/BusRecallBar.h"
#include "ui/bus/DriveLineDialog.h"

#include <QComboBox>
#include <QFile>
#include <QMenu>
#include <QSpinBox>

using namespace opentop;
using namespace opentop::test;

namespace {

class MainWindowMixedFormatsTest : public MainWindowFixture
{
protected:
    void SetUp() override
    {
        // Settings of their own: the bus is remembered, and other test processes run too.
        m_appName = QCoreApplication::applicationName();
        QCoreApplication::setApplicationName(
            QStringLiteral("mixedformats-%1").arg(QCoreApplication::applicationPid()));
        MainWindowFixture::SetUp();
    }
    void TearDown() override
    {
        window.reset();
        QSettings settings;
        settings.clear();
        settings.sync();
        QFile::remove(settings.fileName());
        QCoreApplication::setApplicationName(m_appName);
    }

    static ConnectionSettings mixedBus()
    {
        ConnectionSettings s;
        s.kind = ConnectionSettings::Kind::Simulated;
        s.simSpec = QStringLiteral("dbu200@1,dcpid@7{format=8E1,baud=19200}");
        s.timeoutMs = 100; // the port: 19200 8N1, a DBU bus
        return s;
    }
    void connectMixed()
    {
        bool opened = false;
        QObject::connect(
            window.get(), &MainWindow::connectionChanged, window.get(),
            [&](bool up) { opened = up; }, Qt::SingleShotConnection);
        window->connectTo(mixedBus());
        ASSERT_TRUE(waitFor([&] { return opened; }));
    }
    DriveLineDialog* openDialog()
    {
        DriveLineDialog* dialog = nullptr;
        waitFor([&] {
            dialog = window->findChild<DriveLineDialog*>();
            return dialog && dialog->isVisible();
        });
        return dialog;
    }
    bool live(int slave) const
    {
        const DriveStatus s = window->busPanel()->model()->status(slave);
        return s.online() && s.answered && !window->busPanel()->model()->isStale(slave);
    }
    static void choose(QComboBox* box, const QString& text)
    {
        const int at = box->findText(text);
        ASSERT_GE(at, 0) << qPrintable(text);
        box->setCurrentIndex(at);
    }

    QString m_appName;
};

} // namespace

TEST_F(MainWindowMixedFormatsTest, ADriveAddedWithItsFormatIsLiveBesideTheDbu)
{
    connectMixed();
    BusPanel* panel = window->busPanel();
    panel->startScan(1, 10);
    ASSERT_TRUE(waitFor([&] { return !panel->isScanning(); }, 20000));
    EXPECT_EQ(window->drives()->slaves(), QVector<int>{1});
    EXPECT_TRUE(panel->message().contains(QStringLiteral("another line format than 19200 8N1")))
        << qPrintable(panel->message());
    EXPECT_TRUE(panel->message().contains(QStringLiteral("Add drive")))
        << qPrintable(panel->message());

    // Add drive…: machine number 7 at 19200 8E1.
    QPushButton* add = nullptr;
    for (QPushButton* b : panel->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("A&dd drive…"))
            add = b;
    ASSERT_NE(add, nullptr);
    add->click();
    DriveLineDialog* dialog = openDialog();
    ASSERT_NE(dialog, nullptr);
    EXPECT_TRUE(dialog->findChild<QLabel*>(QStringLiteral("formatHelp"))
                    ->text()
                    .contains(QStringLiteral("None, 2 stop bits")));
    dialog->slaveBox()->setValue(7);
    choose(dialog->formatBox(), QStringLiteral("19200 8E1"));
    dialog->accept();

    ASSERT_TRUE(waitFor([&] {
        return window->drives()->info(7).state == DeviceInfo::State::Present && live(1) && live(7);
    })) << qPrintable(panel->message());
    EXPECT_EQ(window->drives()->info(7).line, (LineFormat{19200, 'E', 8, 1}));
    BusListModel* model = panel->model();
    EXPECT_EQ(model->data(model->index(model->rowOf(7), BusListModel::Family)).toString(),
              QStringLiteral("DCPID at 19200 8E1"));
    EXPECT_EQ(model->data(model->index(model->rowOf(1), BusListModel::Family)).toString(),
              QStringLiteral("DBU"));

    // Both stay live while polled: the port switches between the drives' transactions.
    const QDateTime seen7 = model->status(7).lastAnswer;
    const QDateTime seen1 = model->status(1).lastAnswer;
    ASSERT_TRUE(waitFor([&] {
        return model->status(7).lastAnswer > seen7 && model->status(1).lastAnswer > seen1;
    }));
    EXPECT_TRUE(live(1));
    EXPECT_TRUE(live(7));
}

TEST_F(MainWindowMixedFormatsTest, TheContextMenuSetsTheFormatAndTheBusIsRememberedWithIt)
{
    connectMixed();
    BusPanel* panel = window->busPanel();
    panel->addDrive(7); // at the port's format: no answer, listed as absent
    ASSERT_TRUE(waitFor([&] { return window->drives()->contains(7); }));
    EXPECT_EQ(window->drives()->info(7).state, DeviceInfo::State::Absent);
    panel->addDrive(1);
    ASSERT_TRUE(
        waitFor([&] { return window->drives()->info(1).state == DeviceInfo::State::Present; }));

    std::unique_ptr<QMenu> menu(panel->contextMenuFor({7}, panel));
    QAction* lineFormat = menu->findChild<QAction*>(QStringLiteral("lineFormat"));
    ASSERT_NE(lineFormat, nullptr);
    EXPECT_TRUE(lineFormat->isEnabled());
    lineFormat->trigger();
    DriveLineDialog* dialog = openDialog();
    ASSERT_NE(dialog, nullptr);
    EXPECT_FALSE(dialog->slaveBox()->isVisible()); // the drive's own number
    choose(dialog->formatBox(), QStringLiteral("19200 8E1"));
    dialog->accept();
    ASSERT_TRUE(waitFor([&] {
        return window->drives()->info(7).state == DeviceInfo::State::Present && live(7) && live(1);
    }));

    // A typed format that is none is refused in the dialog, nothing changes.
    menu.reset(panel->contextMenuFor({7}, panel));
    menu->findChild<QAction*>(QStringLiteral("lineFormat"))->trigger();
    dialog = openDialog();
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->formatBox()->currentText(), QStringLiteral("19200 8E1"));
    dialog->formatBox()->setEditText(QStringLiteral("8X1"));
    dialog->accept();
    EXPECT_TRUE(dialog->isVisible());
    EXPECT_FALSE(dialog->problem().isEmpty());
    dialog->reject();
    EXPECT_EQ(window->client()->driveLine(7), (LineFormat{19200, 'E', 8, 1}));

    // Reconnected later: the bus is offered back with drive 7's format. The menu goes first: a
    // new connection makes a new bus list, and the menu is the old one's child.
    menu.reset();
    connectMixed();
    BusRecallBar* bar = window->recallBar();
    ASSERT_TRUE(bar->isVisible());
    EXPECT_TRUE(bar->text().contains(QStringLiteral("19200 8E1"))) << qPrintable(bar->text());
    bar->restoreButton()->click();
    ASSERT_TRUE(waitFor(
        [&] { return window->drives()->info(7).state == DeviceInfo::State::Present && live(7); }));
    EXPECT_EQ(window->client()->driveLine(7), (LineFormat{19200, 'E', 8, 1}));
}
