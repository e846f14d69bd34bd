// Parameter initialisation from the drive's page: the question warns that the link and bus
// control are lost, and afterwards the box offers to reconnect at the profile's factory line
// settings, after the drive's power-on delay.
#include "ui/workspace/ParameterInitBox.h"
#include "model/bus/BusDrives.h"
#include "model/session/DeviceParameters.h"
#include "tests/ui/UiSimFixture.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QPushButton>

using namespace opentop;
using namespace opentop::test;

namespace {

class ParameterInitBoxTest : public UiSimFixture
{
protected:
    void TearDown() override
    {
        box.reset();
        ParameterInitBox::setReconnectHandler(nullptr, nullptr);
        drives.reset();
        UiSimFixture::TearDown();
    }

    // Starts the initialisation and answers its question; returns the question's text.
    QString initialise()
    {
        QString question;
        EXPECT_TRUE(runUntil(box.get(), &ParameterInitBox::finished, [&] {
            box->start();
            EXPECT_TRUE(waitUntil([] {
                return qobject_cast<QMessageBox*>(QApplication::activeModalWidget()) != nullptr;
            }));
            auto* ask = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!ask)
                return;
            question = ask->text() + QLatin1Char('\n') + ask->informativeText();
            ask->button(QMessageBox::Yes)->click();
        }));
        return question;
    }

    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<ParameterInitBox> box;
};

} // namespace

TEST_F(ParameterInitBoxTest, WarnsThenOffersToReconnectAtTheFactoryRate)
{
    startBus(QStringLiteral("dbu200@1"));
    drives = identifiedDrives({1});
    control(1, {QStringLiteral("set"), QStringLiteral("0x1021"), QStringLiteral("4")}); // 38400
    control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")}); // bus
    box = std::make_unique<ParameterInitBox>(drives->parameters(1));
    ConnectionSettings opened;
    int reconnects = 0;
    QObject owner;
    ParameterInitBox::setReconnectHandler(&owner, [&](const ConnectionSettings& s) {
        opened = s;
        ++reconnects;
    });

    const QString question = initialise();
    EXPECT_TRUE(question.contains(QStringLiteral("The link to the drive is lost")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("Bus control is lost"))) << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("reconnect at 19200 bit/s")))
        << qPrintable(question);
    EXPECT_EQ(simRegister(1, 0x1021), 2); // sent: back to the factory rate

    // The simulated connection says 19200 too; the box compares the line it would open.
    const ConnectionSettings factory = box->reconnectSettings();
    EXPECT_EQ(factory.baud, 19200);
    EXPECT_EQ(factory.parity, 'N');
    EXPECT_EQ(factory.stopBits, 1);
    EXPECT_TRUE(box->statusText().contains(QStringLiteral("wait 1 s after power-on")))
        << qPrintable(box->statusText());

    QElapsedTimer timer;
    timer.start();
    box->reconnect();
    EXPECT_EQ(reconnects, 0); // not before the drive's power-on delay
    ASSERT_TRUE(waitUntil([&] { return reconnects == 1; }, 5000));
    EXPECT_GE(timer.elapsed(), 1000);
    EXPECT_EQ(opened.baud, 19200);
    EXPECT_EQ(opened.kind, client->settings().kind);
}

TEST_F(ParameterInitBoxTest, NoReconnectWhenTheLineStays)
{
    startBus(QStringLiteral("dbu200@1"));
    drives = identifiedDrives({1});
    box = std::make_unique<ParameterInitBox>(drives->parameters(1));
    const QString question = initialise();
    EXPECT_FALSE(question.contains(QStringLiteral("is lost"))) << qPrintable(question);
    EXPECT_TRUE(box->reconnectButton()->isHidden());
}
