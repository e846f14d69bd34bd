// Issue 10 item 15: a Connect that fails (a port that does not exist) keeps the connection one
// was working on, and says why.
#include "tests/ui/main/MainWindowFixture.h"

using namespace opentop;
using namespace opentop::test;

using MainWindowConnectTest = MainWindowFixture;

TEST_F(MainWindowConnectTest, AFailedConnectKeepsTheWorkingConnectionAndSaysWhy)
{
    ASSERT_TRUE(waitFor([&] { return window->isConnected(); }));
    BusDrives* drives = window->drives();
    ModbusClient* client = window->client();
    QString warning;
    QTimer poll;
    poll.setInterval(20);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            warning = box->text();
            box->accept();
        }
    });
    poll.start();
    ConnectionSettings missing;
    missing.kind = ConnectionSettings::Kind::Serial;
    missing.port = QStringLiteral("/dev/ttyOpenTOP-does-not-exist");
    window->connectTo(missing);
    ASSERT_TRUE(waitFor([&] { return !warning.isEmpty(); }));
    poll.stop();
    // Said why, and that the old connection stays.
    EXPECT_TRUE(warning.contains(QStringLiteral("ttyOpenTOP-does-not-exist")))
        << qPrintable(warning);
    EXPECT_TRUE(warning.contains(QStringLiteral("Still connected"))) << qPrintable(warning);
    EXPECT_TRUE(window->connectionLabel()->toolTip().contains(QStringLiteral("failed")))
        << qPrintable(window->connectionLabel()->toolTip());
    // The bus is as it was, and still answers.
    EXPECT_TRUE(window->isConnected());
    EXPECT_EQ(window->drives(), drives);
    EXPECT_EQ(window->client(), client);
    EXPECT_EQ(window->drives()->slaves().size(), 4);
    DeviceParameters* params = window->drives()->parameters(1);
    bool read = false;
    params->refresh({}, [&](int failed) { read = failed == 0; });
    EXPECT_TRUE(waitFor([&] { return read; }));

    // A connection that opens replaces the old one.
    ConnectionSettings other;
    other.kind = ConnectionSettings::Kind::Simulated;
    other.simSpec = QStringLiteral("dcpid@9");
    window->connectTo(other, {{9, QStringLiteral("dcpid")}});
    ASSERT_TRUE(waitFor([&] { return window->drives()->slaves() == QVector<int>{9}; }));
    EXPECT_NE(window->client(), client);
}
