#include "ui/connection/ConnectionDialog.h"
#include "ui/connection/DriveFormatsField.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// Keeps QSettings of these tests in a temporary directory under a throw-away name.
class ConnectionDialogTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ASSERT_TRUE(dir.isValid());
        organization = QCoreApplication::organizationName();
        application = QCoreApplication::applicationName();
        QCoreApplication::setOrganizationName(QStringLiteral("OpenTOP-test"));
        QCoreApplication::setApplicationName(QStringLiteral("ConnectionDialogTest"));
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir.path());
    }
    void TearDown() override
    {
        QSettings().clear();
        QCoreApplication::setOrganizationName(organization);
        QCoreApplication::setApplicationName(application);
        QSettings::setDefaultFormat(QSettings::NativeFormat);
    }

    QTemporaryDir dir;
    QString organization;
    QString application;
};

} // namespace

TEST_F(ConnectionDialogTest, RemembersTheAcceptedSettings)
{
    bool found = true;
    ConnectionDialog::remembered(&found);
    EXPECT_FALSE(found);

    ConnectionSettings tcp;
    tcp.kind = ConnectionSettings::Kind::Tcp;
    tcp.host = QStringLiteral("10.0.0.5");
    tcp.tcpPort = 1502;
    tcp.timeoutMs = 300;
    tcp.retries = 2;
    {
        ConnectionDialog dialog;
        dialog.setSettings(tcp);
        dialog.accept();
        EXPECT_EQ(dialog.result(), QDialog::Accepted);
    }
    EXPECT_EQ(QSettings().value(QStringLiteral("connection/kind")).toString(),
              QStringLiteral("tcp"));
    ConnectionDialog again; // starts with what was accepted last
    const ConnectionSettings s = again.settings();
    EXPECT_EQ(s.kind, ConnectionSettings::Kind::Tcp);
    EXPECT_EQ(s.host, QStringLiteral("10.0.0.5"));
    EXPECT_EQ(s.tcpPort, 1502);
    EXPECT_EQ(s.timeoutMs, 300);
    EXPECT_EQ(s.retries, 2);
}

TEST_F(ConnectionDialogTest, ATypedPortPathAndLineSettingsRoundTrip)
{
    ConnectionSettings serial;
    serial.port = QStringLiteral("/dev/pts/3");
    serial.baud = 38400;
    serial.parity = 'O';
    serial.stopBits = 2;
    ConnectionDialog dialog;
    dialog.setSettings(serial);
    dialog.accept();
    ASSERT_EQ(dialog.result(), QDialog::Accepted) << qPrintable(dialog.errorText());
    const ConnectionSettings s = ConnectionDialog::remembered();
    EXPECT_EQ(s.kind, ConnectionSettings::Kind::Serial);
    EXPECT_EQ(s.port, QStringLiteral("/dev/pts/3"));
    EXPECT_EQ(s.baud, 38400);
    EXPECT_EQ(s.parity, 'O');
    EXPECT_EQ(s.stopBits, 2);
}

TEST_F(ConnectionDialogTest, FamilyPresetsFillTheLineSettings)
{
    ConnectionDialog dialog;
    dialog.applyFamilyDefaults(QStringLiteral("dcpid"));
    ConnectionSettings s = dialog.settings();
    EXPECT_EQ(s.baud, 9600);
    EXPECT_EQ(s.parity, 'E');
    EXPECT_EQ(s.stopBits, 1);
    dialog.applyFamilyDefaults(QStringLiteral("dbu"));
    s = dialog.settings();
    EXPECT_EQ(s.baud, 19200);
    EXPECT_EQ(s.parity, 'N');
}

TEST_F(ConnectionDialogTest, InvalidInputIsExplainedAndTheDialogStaysOpen)
{
    ConnectionSettings serial;
    serial.port.clear();
    ConnectionDialog dialog;
    dialog.setSettings(serial);
    dialog.show();
    dialog.accept();
    EXPECT_TRUE(dialog.isVisible());
    EXPECT_NE(dialog.result(), QDialog::Accepted);
    EXPECT_TRUE(dialog.errorText().contains(QStringLiteral("No serial port given")))
        << qPrintable(dialog.errorText());

    ConnectionSettings sim;
    sim.kind = ConnectionSettings::Kind::Simulated;
    sim.simSpec = QStringLiteral("dbu999@1");
    dialog.setSettings(sim);
    dialog.accept();
    EXPECT_TRUE(dialog.isVisible());
    EXPECT_FALSE(dialog.errorText().isEmpty());
    EXPECT_TRUE(dialog.errorText().contains(QStringLiteral("dbu999")))
        << qPrintable(dialog.errorText());
    EXPECT_FALSE(QSettings().contains(QStringLiteral("connection/kind"))); // nothing remembered

    sim.simSpec = QStringLiteral("dbu200@1,dbu400@150,dcpid@7");
    dialog.setSettings(sim);
    dialog.accept();
    EXPECT_FALSE(dialog.isVisible());
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(ConnectionDialog::remembered().simSpec, sim.simSpec);
}

TEST_F(ConnectionDialogTest, OpenErrorsSayWhatToCheck)
{
    ConnectionSettings s;
    s.port = QStringLiteral("/dev/ttyUSB0");
    const QString busy = ConnectionDialog::explainOpenError(
        s, QStringLiteral("Cannot open /dev/ttyUSB0: the port is in use by another OpenTOP "
                          "connection."));
    EXPECT_TRUE(busy.contains(QStringLiteral("another program"))) << qPrintable(busy);
    EXPECT_TRUE(busy.contains(QStringLiteral("in use by another OpenTOP connection")));

    const QString denied = ConnectionDialog::explainOpenError(
        s, QStringLiteral("Cannot open /dev/ttyUSB0 19200 8N1: Permission denied"));
    EXPECT_TRUE(denied.contains(QStringLiteral("sudo usermod -aG dialout $USER")))
        << qPrintable(denied);
    EXPECT_TRUE(denied.contains(QStringLiteral("log out and in")));
    // The serial backend's own text already gives the command: the explanation does not repeat it.
    const QString backendText = QStringLiteral(
        "Cannot open /dev/ttyUSB0 19200 8N1: Permission denied: your user may not open serial "
        "ports. Add it to the dialout group with\n    sudo usermod -aG dialout $USER\nthen log out "
        "and in again (the group applies to new sessions only).");
    const QString once = ConnectionDialog::explainOpenError(s, backendText);
    EXPECT_EQ(once.count(QStringLiteral("usermod")), 1) << qPrintable(once);
    EXPECT_TRUE(once.contains(QStringLiteral("dialout group with the command above")));

    const QString missing = ConnectionDialog::explainOpenError(
        s, QStringLiteral("Cannot open /dev/ttyUSB0 19200 8N1: No such file or directory"));
    EXPECT_TRUE(missing.contains(QStringLiteral("unplugged"))) << qPrintable(missing);
    EXPECT_TRUE(missing.contains(QStringLiteral("/dev/ttyUSB0")));

    const QString silent =
        ConnectionDialog::explainOpenError(s, QStringLiteral("timeout after 2 attempts"));
    EXPECT_TRUE(silent.contains(QStringLiteral("baud rate"))) << qPrintable(silent);
    EXPECT_TRUE(silent.contains(QStringLiteral("parity")));
    EXPECT_TRUE(silent.contains(QStringLiteral("A and B")));
    EXPECT_FALSE(silent.contains(QStringLiteral("dialout")));
}

TEST_F(ConnectionDialogTest, EveryLabelWithAMnemonicHasABuddySoNoAmpersandShows)
{
    ConnectionDialog dialog;
    int checked = 0;
    for (QLabel* label : dialog.findChildren<QLabel*>()) {
        if (!label->text().contains(QLatin1Char('&')) || label->textFormat() == Qt::RichText)
            continue;
        ++checked;
        EXPECT_NE(label->buddy(), nullptr) << qPrintable(label->text());
    }
    EXPECT_GT(checked, 0);
    auto* port = dialog.findChild<QLabel*>(QStringLiteral("portLabel"));
    ASSERT_NE(port, nullptr);
    EXPECT_EQ(port->buddy(), dialog.findChild<QComboBox*>(QStringLiteral("port")));
}

TEST_F(ConnectionDialogTest, Rs485AndLowLatencyRoundTripAndApplyOnlyWhereTheyMatter)
{
    ConnectionSettings serial;
    serial.port = QStringLiteral("/dev/ttyS1");
    serial.rs485 = ConnectionSettings::Rs485::Rts;
    serial.rtsHighWhileSending = false;
    serial.rtsDelayUs = 700;
    serial.lowLatency = false;
    {
        ConnectionDialog dialog;
        dialog.setSettings(serial);
        auto* polarity = dialog.findChild<QComboBox*>(QStringLiteral("rtsPolarity"));
        ASSERT_NE(polarity, nullptr);
        EXPECT_TRUE(polarity->isEnabled());
        const ConnectionSettings s = dialog.settings();
        EXPECT_EQ(s.rs485, ConnectionSettings::Rs485::Rts);
        EXPECT_FALSE(s.rtsHighWhileSending);
        EXPECT_EQ(s.rtsDelayUs, 700);
        EXPECT_FALSE(s.lowLatency);
        dialog.accept();
        ASSERT_EQ(dialog.result(), QDialog::Accepted) << qPrintable(dialog.errorText());
    }
    EXPECT_EQ(QSettings().value(QStringLiteral("connection/rs485")).toString(),
              QStringLiteral("rts"));
    const ConnectionSettings s = ConnectionDialog::remembered();
    EXPECT_EQ(s.rs485, ConnectionSettings::Rs485::Rts);
    EXPECT_FALSE(s.rtsHighWhileSending);
    EXPECT_EQ(s.rtsDelayUs, 700);
    EXPECT_FALSE(s.lowLatency);

    // Defaults: the adapter switches itself, so level and delay are off; low latency on.
    ConnectionDialog fresh;
    fresh.setSettings(ConnectionSettings());
    EXPECT_FALSE(fresh.findChild<QComboBox*>(QStringLiteral("rtsPolarity"))->isEnabled());
    EXPECT_FALSE(fresh.findChild<QWidget*>(QStringLiteral("rtsDelay"))->isEnabled());
    EXPECT_EQ(fresh.settings().rs485, ConnectionSettings::Rs485::Off);
    EXPECT_TRUE(fresh.settings().lowLatency);
}

TEST_F(ConnectionDialogTest, DriveFormatsRoundTripAreCheckedAndTheGuidanceSaysHowToJoin)
{
    ConnectionDialog dialog;
    ConnectionSettings s;
    s.kind = ConnectionSettings::Kind::Serial;
    s.port = QStringLiteral("/dev/ttyUSB0");
    s.baud = 19200;
    s.driveLines.insert(7, LineFormat{9600, 'E', 8, 1});
    dialog.setSettings(s);
    auto* edit = dialog.findChild<QLineEdit*>(QStringLiteral("driveFormats"));
    ASSERT_NE(edit, nullptr);
    EXPECT_EQ(edit->text(), QStringLiteral("7=9600:8E1"));
    edit->setText(QStringLiteral("7=8N2, 9=9600:8O1"));
    const ConnectionSettings read = dialog.settings();
    EXPECT_EQ(read.driveLines.value(7), (LineFormat{19200, 'N', 8, 2}));
    EXPECT_EQ(read.driveLines.value(9), (LineFormat{9600, 'O', 8, 1}));
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(ConnectionDialog::remembered().driveLines, read.driveLines);

    // A typo is named; nothing is accepted.
    ConnectionDialog again;
    again.setSettings(s);
    again.findChild<QLineEdit*>(QStringLiteral("driveFormats"))->setText(QStringLiteral("7=8X1"));
    again.accept();
    EXPECT_NE(again.result(), QDialog::Accepted);
    EXPECT_TRUE(again.errorText().startsWith(QStringLiteral("Drive formats:")))
        << qPrintable(again.errorText());
    EXPECT_TRUE(again.errorText().contains(QStringLiteral("8N1, 8E1, 8O1 or 8N2")));

    // The Mixed bus button's text: which register, the storage rule, the order of the steps.
    const QString guidance = DriveFormatsField::guidance();
    for (const char* part : {"0x008C", "None, 2 stop bits", "0x10", "15 registers", "next power-up",
                             "switch it off and on", "1.", "4."})
        EXPECT_TRUE(guidance.contains(QLatin1String(part))) << part;
}
