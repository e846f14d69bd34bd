#include "ui/pages/RunningDataPage.h"
#include "model/session/DeviceParameters.h"
#include "tests/ui/pages/PageFixture.h"
#include "ui/workspace/ParameterField.h"

#include <QApplication>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>

using namespace opentop;

namespace {

// Types `text` into `w` key by key, as a user would (textEdited fires), optionally confirming.
void type(QWidget* w, const QString& text, bool confirm)
{
    w->setFocus();
    for (const QChar c : text) {
        QKeyEvent press(QEvent::KeyPress, 0, Qt::NoModifier, QString(c));
        QCoreApplication::sendEvent(w, &press);
    }
    if (confirm) {
        QKeyEvent enter(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
        QCoreApplication::sendEvent(w, &enter);
    }
}

QString registerOn(SimBus& bus, const char* address)
{
    return bus.control(1, {QStringLiteral("get"), QLatin1String(address)}).text;
}

} // namespace

class RunningDataPageTest : public test::PageFixture<RunningDataPage>
{
protected:
    QLineEdit* edit(const char* name)
    {
        return qobject_cast<QLineEdit*>(page->field(QLatin1String(name))->editor());
    }
};

TEST_F(RunningDataPageTest, ShowsTheGridWithUnitsAndTheVariantsSpeedRange)
{
    EXPECT_EQ(edit("spno2.speed")->text(), QStringLiteral("1000"));
    EXPECT_EQ(edit("spno2.accel")->text(), QStringLiteral("0.5"));
    for (int spno = 2; spno <= 8; ++spno) {
        for (const char* c : {"speed", "accel", "decel", "direction"})
            EXPECT_TRUE(page->field(QStringLiteral("spno%1.%2").arg(spno).arg(QLatin1String(c))));
        EXPECT_TRUE(page->initializeButton(spno));
    }
    EXPECT_TRUE(page->rangeText().contains(QStringLiteral("DBU200-D")))
        << qPrintable(page->rangeText());
    EXPECT_TRUE(page->rangeText().contains(QStringLiteral("250–3000 r/min")));
    EXPECT_FALSE(page->parameterNames().contains(QStringLiteral("spno2.init")));
    EXPECT_TRUE(page->parameterNames().contains(QStringLiteral("spno8.decel")));
}

TEST_F(RunningDataPageTest, AnEditedSpeedIsWrittenToTheDrive)
{
    edit("spno2.speed")->selectAll();
    type(edit("spno2.speed"), QStringLiteral("1500"), true);
    ASSERT_EQ(parameters->entry(QStringLiteral("spno2.speed"))->state,
              DeviceParameters::State::Pending);
    ASSERT_TRUE(run([this] { page->writePage(); }));
    EXPECT_EQ(parameters->entry(QStringLiteral("spno2.speed"))->state,
              DeviceParameters::State::Clean);
    EXPECT_TRUE(registerOn(*bus, "0xCA03").contains(QStringLiteral("= 1500 ")))
        << qPrintable(registerOn(*bus, "0xCA03"));
}

TEST_F(RunningDataPageTest, AnInvalidSpeedIsRefusedAsTypedAndNothingIsSent)
{
    const int before = framesSent();
    QLineEdit* speed = edit("spno3.speed");
    speed->selectAll();
    type(speed, QStringLiteral("100"), false);
    ParameterField* f = page->field(QStringLiteral("spno3.speed"));
    EXPECT_TRUE(f->problem().contains(QStringLiteral("250–3000"))) << qPrintable(f->problem());
    EXPECT_TRUE(speed->toolTip().contains(QStringLiteral("250–3000")));
    type(speed, QString(), true);
    EXPECT_FALSE(f->problem().isEmpty());
    EXPECT_NE(parameters->entry(QStringLiteral("spno3.speed"))->state,
              DeviceParameters::State::Pending);
    page->writePage();
    QCoreApplication::processEvents();
    EXPECT_EQ(framesSent(), before);
}

TEST_F(RunningDataPageTest, Spno1SpeedIsReadOnlyAndHasNoTimeRegisters)
{
    QLineEdit* speed = edit("spno1.speed");
    ASSERT_TRUE(speed);
    EXPECT_TRUE(speed->isReadOnly());
    EXPECT_TRUE(speed->toolTip().contains(QStringLiteral("read-only")))
        << qPrintable(speed->toolTip());
    page->field(QStringLiteral("spno1.speed"))->enter(QStringLiteral("1000"));
    EXPECT_TRUE(parameters->pendingNames().isEmpty());
    EXPECT_FALSE(page->field(QStringLiteral("spno1.accel")));
    EXPECT_FALSE(page->field(QStringLiteral("spno1.decel")));
    bool ssNoted = false;
    for (QLabel* l : page->findChildren<QLabel*>())
        ssNoted = ssNoted || (l->text() == QStringLiteral("SS trimmer") &&
                              l->toolTip().contains(QStringLiteral("no acceleration register")));
    EXPECT_TRUE(ssNoted);
    EXPECT_TRUE(page->field(QStringLiteral("spno1.direction")));
}

TEST_F(RunningDataPageTest, APendingEditSurvivesABackgroundRefresh)
{
    page->field(QStringLiteral("spno3.speed"))->enter(QStringLiteral("2000"));
    control(1, {QStringLiteral("set"), QStringLiteral("0xCA05"), QStringLiteral("1200")});
    ASSERT_TRUE(run([this] { page->refresh(); }));
    const DeviceParameters::Entry* e = parameters->entry(QStringLiteral("spno3.speed"));
    EXPECT_EQ(e->device.raw, 1200);
    EXPECT_EQ(e->state, DeviceParameters::State::Pending);
    EXPECT_EQ(edit("spno3.speed")->text(), QStringLiteral("2000"));
    EXPECT_TRUE(edit("spno3.speed")->styleSheet().contains(QStringLiteral("#ef8f00")));
    EXPECT_TRUE(edit("spno3.speed")->toolTip().contains(QStringLiteral("1200 r/min")));
}

TEST_F(RunningDataPageTest, InitializeAsksNamingTheDefaultsAndResetsTheRow)
{
    control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("2222")});
    control(1, {QStringLiteral("set"), QStringLiteral("0x1303"), QStringLiteral("50")});
    ASSERT_TRUE(run([this] { page->refresh(); }));
    ASSERT_EQ(edit("spno2.speed")->text(), QStringLiteral("2222"));

    // First answer Cancel: nothing is sent.
    QString asked;
    auto answer = [&asked](QMessageBox::StandardButton which) {
        QTimer::singleShot(0, [&asked, which] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            ASSERT_TRUE(box);
            asked = box->text() + QLatin1Char('\n') + box->informativeText();
            box->button(which)->click();
        });
    };
    const int before = framesSent();
    answer(QMessageBox::Cancel);
    page->initializeButton(2)->click();
    EXPECT_EQ(framesSent(), before);
    EXPECT_TRUE(asked.contains(QStringLiteral("SPno2")));

    answer(QMessageBox::Yes);
    ASSERT_TRUE(run([this] { page->initializeButton(2)->click(); }));
    EXPECT_TRUE(asked.contains(QStringLiteral("SPno2 speed: 1000 r/min"))) << qPrintable(asked);
    EXPECT_TRUE(asked.contains(QStringLiteral("SPno2 acceleration time: 0.5 s")));
    EXPECT_TRUE(asked.contains(QStringLiteral("SPno2 direction: CW")));
    EXPECT_TRUE(registerOn(*bus, "0xCA03").contains(QStringLiteral("= 1000 ")));
    EXPECT_TRUE(registerOn(*bus, "0x1303").contains(QStringLiteral("= 5 ")));
    EXPECT_EQ(edit("spno2.speed")->text(), QStringLiteral("1000"));
    EXPECT_EQ(edit("spno2.accel")->text(), QStringLiteral("0.5"));
}

TEST_F(RunningDataPageTest, TabMovesRowByRow)
{
    // The next widget Tab reaches from `w`.
    auto next = [](QWidget* w) {
        for (QWidget* n = w->nextInFocusChain(); n != w; n = n->nextInFocusChain()) {
            if ((n->focusPolicy() & Qt::TabFocus) && n->isVisibleTo(w->window()) && n->isEnabled())
                return n;
        }
        return w;
    };
    ParameterField* speed = page->field(QStringLiteral("spno2.speed"));
    EXPECT_EQ(next(speed->editor()), page->field(QStringLiteral("spno2.accel"))->editor());
    QWidget* direction = page->field(QStringLiteral("spno2.direction"))->editor();
    EXPECT_EQ(next(direction), page->initializeButton(2));
    EXPECT_EQ(next(page->initializeButton(2)),
              page->field(QStringLiteral("spno3.speed"))->editor());
}

TEST_F(RunningDataPageTest, WithTheVariantUnknownASpeedMustSuitEveryVariant)
{
    page.reset();
    session(1)->setVariant(QString());
    page = std::make_unique<RunningDataPage>(parameters.get());
    EXPECT_TRUE(page->rangeText().contains(QStringLiteral("DBU200-D: 0 or 250–3000 r/min")))
        << qPrintable(page->rangeText());
    EXPECT_TRUE(page->rangeText().contains(QStringLiteral("DBU400-D4: 0 or 300–3000 r/min")));
    ParameterField* speed = page->field(QStringLiteral("spno4.speed"));
    speed->enter(QStringLiteral("270"));
    EXPECT_FALSE(speed->problem().isEmpty());
    // Kept as an invalid edit, to correct or revert; never written.
    EXPECT_EQ(parameters->invalidNames(), QStringList{QStringLiteral("spno4.speed")});
    speed->enter(QStringLiteral("300"));
    EXPECT_TRUE(speed->problem().isEmpty()) << qPrintable(speed->problem());
    EXPECT_EQ(parameters->pendingNames(), QStringList{QStringLiteral("spno4.speed")});
}
