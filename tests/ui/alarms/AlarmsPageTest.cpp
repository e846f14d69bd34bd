// The alarms page, the alarm banner and the CSV export against the in-process simulated DBU.
#include "ui/alarms/AlarmsPage.h"
#include "model/bus/BusDrives.h"
#include "model/bus/DriveStatusPoller.h"
#include "tests/support/FifoReader.h"
#include "tests/ui/UiSimFixture.h"
#include "ui/alarms/AlarmBanner.h"
#include "ui/alarms/AlarmExport.h"

#include <QApplication>
#include <QFile>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

class AlarmsPageTest : public UiSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1"));
        // Alarms clear by Alarm-Reset; the drive listens to commands over the bus.
        control(1, {QStringLiteral("set"), QStringLiteral("0x1005"), QStringLiteral("1")});
        communicationPriority(1);
    }

    void TearDown() override
    {
        page.reset();
        UiSimFixture::TearDown();
    }

    void openPage()
    {
        page = std::make_unique<AlarmsPage>(session(1));
        page->show();
        ASSERT_TRUE(
            runUntil(page.get(), &AlarmsPage::operationFinished, [this] { page->refresh(); }));
    }

    // The confirmation the page shows, answered; its text and informative text.
    QString answer(QMessageBox::StandardButton button)
    {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        EXPECT_TRUE(box);
        if (!box)
            return QString();
        const QString text = box->text() + QLatin1Char('\n') + box->informativeText();
        box->button(button)->click();
        return text;
    }

    // Starts a command, confirms it and waits until the page has read the drive again.
    QString confirmAndRun(const std::function<void()>& start)
    {
        QString question;
        EXPECT_TRUE(runUntil(page.get(), &AlarmsPage::operationFinished, [&] {
            start();
            question = answer(QMessageBox::Yes);
        }));
        return question;
    }

    std::unique_ptr<AlarmsPage> page;
};

} // namespace

TEST_F(AlarmsPageTest, AlarmAndWarningAppearWithCauseAndRemedy)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("3")});
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    control(1, {QStringLiteral("warning"), QStringLiteral("23")});
    openPage();
    QTableWidget* alarms = page->alarmTable();
    ASSERT_EQ(alarms->rowCount(), 2);
    EXPECT_EQ(alarms->item(0, 0)->text(), QStringLiteral("1"));
    EXPECT_EQ(alarms->item(0, 1)->text(), QStringLiteral("07h"));
    EXPECT_EQ(alarms->item(0, 2)->text(), QStringLiteral("AL007"));
    EXPECT_EQ(alarms->item(0, 3)->text(), QStringLiteral("Overload"));
    EXPECT_EQ(alarms->item(0, 4)->text(), QStringLiteral("Alarm-Reset"));
    EXPECT_EQ(alarms->item(1, 2)->text(), QStringLiteral("AL003"));
    ASSERT_EQ(page->warningTable()->rowCount(), 1);
    EXPECT_EQ(page->warningTable()->item(0, 2)->text(), QStringLiteral("WR017"));

    const CodeEntry overload = *page->report().histories[0].records[0].entry;
    ASSERT_FALSE(overload.remedy.isEmpty());
    alarms->selectRow(0);
    EXPECT_TRUE(page->detailText().contains(overload.remedy)) << qPrintable(page->detailText());
    EXPECT_TRUE(page->detailText().contains(overload.cause));
    page->warningTable()->selectRow(0);
    EXPECT_TRUE(page->detailText().startsWith(QStringLiteral("WR017")));
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("Alarm active: AL007 Overload")))
        << qPrintable(page->statusText());
    EXPECT_EQ(page->commErrorText(), QStringLiteral("status.comm_error: no error (0)."));
}

TEST_F(AlarmsPageTest, CommunicationErrorRegisterIsDecoded)
{
    control(1, {QStringLiteral("set"), QStringLiteral("0x007B"), QStringLiteral("0xE2"),
                QStringLiteral("4")});
    openPage();
    EXPECT_TRUE(page->commErrorText().startsWith(
        QStringLiteral("status.comm_error: E2h Cannot execute command")))
        << qPrintable(page->commErrorText());
}

TEST_F(AlarmsPageTest, ResetClearsAnAlarmTheResetCommandClears)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    openPage();
    const QString question = confirmAndRun([this] { page->resetAlarm(); });
    EXPECT_TRUE(question.contains(QStringLiteral("cmd.alarm_reset"))) << qPrintable(question);
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("AL007 Overload is cleared.")))
        << qPrintable(page->statusText());
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("No alarm is active.")));
    EXPECT_EQ(page->alarmTable()->rowCount(), 1); // the record stays
}

TEST_F(AlarmsPageTest, ResetExplainsAnAlarmOnlyAPowerCycleClears)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("1")});
    openPage();
    confirmAndRun([this] { page->resetAlarm(); });
    EXPECT_TRUE(page->statusText().contains(
        QStringLiteral("AL001 Overvoltage is still active: only a power cycle clears it.")))
        << qPrintable(page->statusText());
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("Turn the drive's power off")));
}

TEST_F(AlarmsPageTest, CancelledResetSendsNothing)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    openPage();
    const int writes = writesSent();
    page->resetAlarm();
    answer(QMessageBox::Cancel);
    waitUntil([] { return false; }, 100);
    EXPECT_EQ(writesSent(), writes);
    EXPECT_FALSE(page->isBusy());
}

TEST_F(AlarmsPageTest, ClearRecordsNamesWhatIsErasedAndEmptiesTheTables)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    control(1, {QStringLiteral("warning"), QStringLiteral("23")});
    openPage();
    ASSERT_EQ(page->alarmTable()->rowCount(), 1);
    const QString question = confirmAndRun([this] { page->clearRecords(); });
    EXPECT_TRUE(question.contains(QStringLiteral("Alarm codes (1 records)")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("Warning codes (1 records)")));
    EXPECT_EQ(page->alarmTable()->rowCount(), 0);
    EXPECT_EQ(page->warningTable()->rowCount(), 0);
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("read back empty")))
        << qPrintable(page->statusText());
}

TEST_F(AlarmsPageTest, ClosingThePageDuringACommandIsSafe)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    openPage();
    page->refresh();
    ASSERT_TRUE(page->isBusy());
    page.reset();
    waitUntil([] { return false; }, 300);
    SUCCEED();
}

namespace {

class AlarmBusTest : public UiSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1,dbu400@2"));
        drives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
        for (int slave : {1, 2}) {
            DeviceInfo info;
            info.slave = slave;
            info.state = DeviceInfo::State::Present;
            info.family = QStringLiteral("dbu");
            info.model = slave == 1 ? QStringLiteral("DBU200-D") : QStringLiteral("DBU400-D");
            drives->update(info);
        }
    }

    void TearDown() override
    {
        banner.reset();
        poller.reset();
        drives.reset();
        UiSimFixture::TearDown();
    }

    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<DriveStatusPoller> poller;
    std::unique_ptr<AlarmBanner> banner;
};

} // namespace

TEST_F(AlarmBusTest, BannerShowsAnAlarmWithItsRemedyUntilDismissed)
{
    poller = std::make_unique<DriveStatusPoller>(drives.get());
    poller->setInterval(20);
    banner = std::make_unique<AlarmBanner>(poller.get());
    poller->start();
    ASSERT_TRUE(waitUntil([this] { return poller->cyclesCompleted() >= 1; }));
    EXPECT_FALSE(banner->hasAlarm());
    EXPECT_TRUE(banner->isHidden());

    control(2, {QStringLiteral("alarm"), QStringLiteral("7")});
    ASSERT_TRUE(waitUntil([this] { return banner->hasAlarm(); }));
    EXPECT_EQ(banner->currentSlave(), 2);
    EXPECT_TRUE(banner->isVisible());
    const DriveStatus s = poller->status(2);
    ASSERT_TRUE(s.alarm);
    EXPECT_EQ(banner->text(), QStringLiteral("Machine 2: AL007 Overload — ") + s.alarm->remedy);

    int shown = 0;
    QObject::connect(banner.get(), &AlarmBanner::showAlarms,
                     [&shown](int slave) { shown = slave; });
    for (QPushButton* b : banner->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("Show"))
            b->click();
    EXPECT_EQ(shown, 2);

    banner->dismiss();
    EXPECT_FALSE(banner->hasAlarm());
    const int cycles = poller->cyclesCompleted();
    ASSERT_TRUE(waitUntil([&] { return poller->cyclesCompleted() >= cycles + 2; }));
    EXPECT_FALSE(banner->hasAlarm()); // the dismissed alarm stays hidden while it lasts

    control(1, {QStringLiteral("alarm"), QStringLiteral("1")});
    ASSERT_TRUE(waitUntil([this] { return banner->hasAlarm(); }));
    EXPECT_EQ(banner->currentSlave(), 1);
    EXPECT_TRUE(banner->text().startsWith(QStringLiteral("Machine 1: AL001 Overvoltage")));
}

TEST_F(AlarmBusTest, CsvTextHoldsEveryRecordWithItsRemedy)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    control(1, {QStringLiteral("warning"), QStringLiteral("23")});
    AlarmHistory history(drives->session(1));
    AlarmExport::DriveReport d;
    d.slave = 1;
    d.model = QStringLiteral("DBU200-D");
    d.name = QStringLiteral("Infeed, conveyor 3"); // the comma is quoted
    d.report = await<AlarmHistory::Report>([&](auto done) { history.read(done); });
    ASSERT_TRUE(d.report.ok);
    const CodeEntry overload = *d.report.histories[0].records[0].entry;
    const QString text = AlarmExport::csv({d});
    const QStringList lines = text.split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 3) << qPrintable(text);
    EXPECT_EQ(lines[0], QStringLiteral("Machine,Machine name,Model,Kind,Record,Code,Panel code,"
                                       "Name,Cleared by,Cause,Remedy"));
    EXPECT_TRUE(lines[1].startsWith(QStringLiteral(
        "1,\"Infeed, conveyor 3\",DBU200-D,alarm,1,07h,AL007,Overload,Alarm-Reset,")))
        << qPrintable(lines[1]);
    EXPECT_TRUE(text.contains(overload.remedy) ||
                text.contains(QLatin1Char('"') + overload.remedy + QLatin1Char('"')));
    // The remedy names the setting as the program shows it, not its register address.
    EXPECT_FALSE(overload.remedy.contains(QStringLiteral("0x1011"))) << qPrintable(overload.remedy);
    EXPECT_TRUE(overload.remedy.contains(
        QStringLiteral("Overload alarm output time (Alarm/warning parameters)")))
        << qPrintable(overload.remedy);
    EXPECT_TRUE(lines[2].startsWith(
        QStringLiteral("1,\"Infeed, conveyor 3\",DBU200-D,warning,1,17h,WR017,")));
}

TEST_F(AlarmBusTest, ExportWritesTheFileOfAllDrives)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    control(2, {QStringLiteral("alarm"), QStringLiteral("1")});
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("alarms.csv"));
    AlarmExport exporter(drives.get());
    bool ok = false;
    QString message;
    QObject::connect(&exporter, &AlarmExport::finished, [&](bool o, const QString& m) {
        ok = o;
        message = m;
    });
    ASSERT_TRUE(runUntil(&exporter, &AlarmExport::finished, [&] {
        ASSERT_TRUE(exporter.exportTo(path));
        EXPECT_TRUE(exporter.isBusy());
    }));
    EXPECT_TRUE(ok) << qPrintable(message);
    EXPECT_TRUE(message.startsWith(QStringLiteral("2 record(s) of 2 drive(s)")))
        << qPrintable(message);
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    EXPECT_EQ(text, AlarmExport::csv(exporter.reports()));
    // Machine, its name (none given), model, kind, record, code, panel code, name.
    EXPECT_TRUE(text.contains(QStringLiteral("2,,DBU400-D,alarm,1,01h,AL001,Overvoltage")));
}

TEST_F(AlarmBusTest, ExportToAFifoWritesThroughItAndToAMissingFolderFails)
{
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    QTemporaryDir dir;
    AlarmExport exporter(drives.get());
    bool ok = false;
    QString message;
    QObject::connect(&exporter, &AlarmExport::finished, [&](bool o, const QString& m) {
        ok = o;
        message = m;
    });
    bool stillFifo = false;
    const QByteArray got = test::saveThroughFifo(
        dir.path(),
        [&](const QString& path) {
            ASSERT_TRUE(runUntil(&exporter, &AlarmExport::finished,
                                 [&] { ASSERT_TRUE(exporter.exportTo(path)); }));
        },
        &stillFifo);
    EXPECT_TRUE(ok) << qPrintable(message);
    EXPECT_TRUE(stillFifo) << "the FIFO was replaced by a regular file";
    EXPECT_EQ(QString::fromUtf8(got), AlarmExport::csv(exporter.reports()));

    const QString missing = dir.filePath(QStringLiteral("no-such-folder/alarms.csv"));
    ASSERT_TRUE(runUntil(&exporter, &AlarmExport::finished,
                         [&] { ASSERT_TRUE(exporter.exportTo(missing)); }));
    EXPECT_FALSE(ok);
    EXPECT_TRUE(message.startsWith(QStringLiteral("cannot write ") + missing))
        << qPrintable(message);
    EXPECT_FALSE(QFile::exists(missing));
}
