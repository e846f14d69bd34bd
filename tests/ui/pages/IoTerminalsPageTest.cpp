#include "ui/pages/IoTerminalsPage.h"
#include "model/session/DeviceParameters.h"
#include "tests/ui/pages/PageFixture.h"
#include "ui/workspace/ParameterField.h"

#include <QComboBox>

using namespace opentop;

class IoTerminalsPageTest : public test::PageFixture<IoTerminalsPage>
{
protected:
    QComboBox* combo(const QString& name)
    {
        return qobject_cast<QComboBox*>(page->field(name)->editor());
    }

    // The codes a chooser offers (without a "not valid now" entry for the current value).
    QList<int> offered(const QString& name)
    {
        QList<int> codes;
        QComboBox* c = combo(name);
        for (int i = 0; i < c->count(); ++i) {
            if (!c->itemText(i).contains(QStringLiteral("not valid")))
                codes << c->itemData(i).toString().toInt();
        }
        return codes;
    }

    QString registerOn(const char* address)
    {
        return bus->control(1, {QStringLiteral("get"), QLatin1String(address)}).text;
    }
};

TEST_F(IoTerminalsPageTest, OffersOnlyMode2FunctionsByDefault)
{
    for (int x = 0; x < 4; ++x) {
        const QString name = QStringLiteral("io.x%1").arg(x);
        ASSERT_TRUE(combo(name)) << qPrintable(name);
        const QList<int> codes = offered(name);
        EXPECT_EQ(codes.size(), 9);
        for (int code : codes)
            EXPECT_GE(code, 0x10) << qPrintable(name);
    }
    EXPECT_EQ(combo(QStringLiteral("io.x0"))->currentText(), QStringLiteral("CW/STOP"));
    EXPECT_TRUE(page->description(QStringLiteral("io.x0")).startsWith(QStringLiteral("CW/STOP")));
    EXPECT_EQ(combo(QStringLiteral("io.y0"))->currentText(), QStringLiteral("Speed-Out"));
    EXPECT_TRUE(page->description(QStringLiteral("io.y0")).contains(QStringLiteral("24")));
    EXPECT_TRUE(page->invalidTerminals().isEmpty());
    EXPECT_TRUE(page->flagText().isEmpty());
    EXPECT_TRUE(combo(QStringLiteral("core.control_priority")));
}

TEST_F(IoTerminalsPageTest, APendingModeSwitchOffersMode1CodesAndFlagsTheInputs)
{
    page->field(QStringLiteral("core.control_mode"))->enter(QStringLiteral("Mode1"));
    ASSERT_EQ(parameters->entry(QStringLiteral("core.control_mode"))->state,
              DeviceParameters::State::Pending);
    for (int x = 0; x < 4; ++x) {
        const QString name = QStringLiteral("io.x%1").arg(x);
        for (int code : offered(name))
            EXPECT_LT(code, 0x10) << qPrintable(name);
        EXPECT_TRUE(combo(name)->currentText().contains(QStringLiteral("not valid")));
    }
    EXPECT_EQ(page->invalidTerminals(),
              QStringList({QStringLiteral("io.x0"), QStringLiteral("io.x1"),
                           QStringLiteral("io.x2"), QStringLiteral("io.x3")}));
    EXPECT_TRUE(page->flagText().contains(QStringLiteral("X0, X1, X2, X3")))
        << qPrintable(page->flagText());
    EXPECT_TRUE(page->flagText().contains(QStringLiteral("Mode1")));

    // Re-choosing one clears its flag; reverting the mode brings back the Mode2 choices.
    page->field(QStringLiteral("io.x0"))->enter(QStringLiteral("RUN/STOP"));
    EXPECT_EQ(combo(QStringLiteral("io.x0"))->currentText(), QStringLiteral("RUN/STOP"));
    EXPECT_FALSE(page->invalidTerminals().contains(QStringLiteral("io.x0")));
    parameters->revert(QStringLiteral("core.control_mode"));
    EXPECT_GE(offered(QStringLiteral("io.x1")).first(), 0x10);
    EXPECT_EQ(page->invalidTerminals(), QStringList{QStringLiteral("io.x0")});
}

TEST_F(IoTerminalsPageTest, WritingPutsTheModeAndTheTerminalsOnTheDrive)
{
    page->field(QStringLiteral("core.control_mode"))->enter(QStringLiteral("Mode1"));
    page->useModeDefaults(); // X0 RUN/STOP, X1 CW/CCW, X2 M0, X3 M1
    EXPECT_TRUE(page->invalidTerminals().isEmpty()) << qPrintable(page->flagText());
    page->field(QStringLiteral("io.x3"))->enter(QStringLiteral("H-Free (hold/free)"));
    page->field(QStringLiteral("io.y1"))->enter(QStringLiteral("Move-Out"));
    ASSERT_EQ(parameters->pendingNames().size(), 6);
    ASSERT_TRUE(run([this] { page->writePage(); }));
    EXPECT_TRUE(parameters->pendingNames().isEmpty());
    EXPECT_TRUE(registerOn("0x2015").contains(QStringLiteral("= 0 ")));
    EXPECT_TRUE(registerOn("0x2101").contains(QStringLiteral("= 1 ")));
    EXPECT_TRUE(registerOn("0x2103").contains(QStringLiteral("= 2 ")));
    EXPECT_TRUE(registerOn("0x2105").contains(QStringLiteral("= 5 ")));
    EXPECT_TRUE(registerOn("0x2107").contains(QStringLiteral("= 9 ")));
    EXPECT_TRUE(registerOn("0x210B").contains(QStringLiteral("= 6 ")));
    EXPECT_TRUE(page->invalidTerminals().isEmpty());
    EXPECT_EQ(combo(QStringLiteral("io.x0"))->currentText(), QStringLiteral("RUN/STOP"));
    for (int code : offered(QStringLiteral("io.x2")))
        EXPECT_LT(code, 0x10);
}
