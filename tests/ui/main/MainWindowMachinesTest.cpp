// Issue 24 item 8 in the real window: a DBU's variant asked when it is needed (once, saying what
// it changes, remembered for the bus), each family's own address switches, and names for
// machines — given in the bus list, shown on pages and in questions and files, kept per bus.
#include "tests/ui/main/MainWindowFixture.h"

#include "model/bus/BusMemory.h"
#include "ui/files/BackupDialog.h"

#include <QDialog>
#include <QFile>
#include <QHeaderView>
#include <QInputDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenu>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

class MainWindowMachinesTest : public MainWindowFixture
{
protected:
    ConnectionSettings simulated() const
    {
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.simSpec = QStringLiteral("dbu200@1,dbu200@2,dbu400@150,dcpid@7");
        settings.timeoutMs = 100;
        return settings;
    }

    // Connects as the connection dialog does (no drives named), then adds `slaves` by number:
    // a DBU added so reports only "DBU", its variant unknown.
    void connectUnnamed(const QVector<int>& slaves)
    {
        bool opened = false;
        QObject::connect(
            window.get(), &MainWindow::connectionChanged, window.get(),
            [&](bool up) { opened = up; }, Qt::SingleShotConnection);
        window->connectTo(simulated());
        ASSERT_TRUE(waitFor([&] { return opened; }));
        for (int slave : slaves)
            window->busPanel()->addDrive(slave);
        ASSERT_TRUE(waitFor([&] {
            for (int slave : slaves)
                if (window->drives()->info(slave).state != DeviceInfo::State::Present)
                    return false;
            return true;
        }));
    }

    // Runs `answer` on the next modal dialog that `matches`, once.
    void whenModal(const std::function<bool(QWidget*)>& matches,
                   const std::function<void(QWidget*)>& answer)
    {
        auto* timer = new QTimer(window.get());
        QObject::connect(timer, &QTimer::timeout, timer, [timer, matches, answer] {
            QWidget* w = QApplication::activeModalWidget();
            if (!w || !matches(w))
                return;
            timer->stop();
            timer->deleteLater();
            answer(w);
        });
        timer->start(20);
    }
    static bool isVariantQuestion(QWidget* w)
    {
        return w->objectName() == QLatin1String("variantQuestion");
    }

    TestRunPanel* testRun(int slave)
    {
        select({slave});
        TestRunPanel* panel = nullptr;
        waitFor([&] {
            QTabWidget* tabs = window->workspace()->tabs();
            for (int i = 0; i < tabs->count(); ++i) {
                auto* p = tabs->widget(i)->findChild<TestRunPanel*>();
                if (p && p->slave() == slave &&
                    window->workspace()->drive() == window->drives()->parameters(slave)) {
                    tabs->setCurrentIndex(i);
                    panel = p;
                }
            }
            return panel != nullptr;
        });
        return panel;
    }

    // Clicks Start and returns the start question's text (answered No: nothing starts).
    QString startQuestion(TestRunPanel* panel)
    {
        QString text;
        whenModal([](QWidget* w) { return w->objectName() != QLatin1String("variantQuestion"); },
                  [&text](QWidget* w) {
                      auto* box = qobject_cast<QMessageBox*>(w);
                      text = box ? box->text() : QStringLiteral("?");
                      if (box)
                          box->reject();
                  });
        panel->findChild<QPushButton*>(QStringLiteral("start"))->click();
        waitFor([&] { return !text.isEmpty(); });
        return text;
    }
};

} // namespace

TEST_F(MainWindowMachinesTest, ADrivesVariantIsAskedOnceWhenAStartNeedsItAndRemembered)
{
    connectUnnamed({150});
    ASSERT_TRUE(window->drives()->info(150).variantUnknown());
    bus->control(150, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    TestRunPanel* panel = testRun(150);
    ASSERT_NE(panel, nullptr);
    ASSERT_TRUE(waitFor([&] { return panel->commandsEnabled(); }));
    QString question;
    whenModal(isVariantQuestion, [&question](QWidget* w) {
        auto* box = qobject_cast<QMessageBox*>(w);
        question = box->text();
        // Cancel is the default: nothing is assumed on Enter.
        EXPECT_EQ(box->defaultButton(), box->button(QMessageBox::Cancel));
        box->findChild<QPushButton*>(QStringLiteral("variant_dbu400"))->click();
    });
    const QString start = startQuestion(panel);
    EXPECT_TRUE(question.contains(QStringLiteral("machine number 150"))) << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("DBU200-D or DBU400-D4"))) << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("48 V, 400 W"))) << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("0 or 300–3000 r/min"))) << qPrintable(question);
    // Then the start question, for the variant now known; nothing started (answered No).
    EXPECT_TRUE(start.contains(QStringLiteral("starts the motor"))) << qPrintable(start);
    EXPECT_EQ(speedOf(150), 0);
    EXPECT_EQ(window->drives()->info(150).variant, QStringLiteral("dbu400"));
    EXPECT_EQ(window->drives()->info(150).model, QStringLiteral("DBU400-D4"));
    // Remembered with the drives of this bus, for the next connection and the command line.
    EXPECT_EQ(BusMemory::types(BusMemory::load(BusMemory::key(simulated()))).value(150),
              QStringLiteral("dbu400"));
    // Asked once: the next start goes straight to its own question.
    bool asked = false;
    whenModal(isVariantQuestion, [&asked](QWidget* w) {
        asked = true;
        qobject_cast<QMessageBox*>(w)->reject();
    });
    EXPECT_FALSE(startQuestion(panel).isEmpty());
    EXPECT_FALSE(asked);
}

TEST_F(MainWindowMachinesTest, AnEditThatDependsOnTheVariantAsksItAndNotKnownIsAnAnswerToo)
{
    connectUnnamed({2});
    select({2});
    DeviceParameters* params = window->drives()->parameters(2);
    ASSERT_TRUE(waitFor([&] { return window->workspace()->drive() == params; }));
    ParameterField* speed = nullptr;
    ParameterField* accel = nullptr;
    for (ParameterField* f : window->workspace()->findChildren<ParameterField*>()) {
        speed = f->parameterName() == QLatin1String("spno2.speed") ? f : speed;
        accel = f->parameterName() == QLatin1String("spno2.accel") ? f : accel;
    }
    ASSERT_TRUE(speed && accel);
    // An acceleration does not depend on the variant: nothing asked.
    accel->enter(QStringLiteral("3.5"));
    EXPECT_TRUE(params->pendingNames().contains(QStringLiteral("spno2.accel")));
    // A speed does: asked before the edit is judged. "Not known": checked against both.
    whenModal(isVariantQuestion, [](QWidget* w) {
        w->findChild<QPushButton*>(QStringLiteral("variantUnknown"))->click();
    });
    speed->enter(QStringLiteral("280"));
    ASSERT_TRUE(
        waitFor([&] { return params->pendingNames().contains(QStringLiteral("spno2.speed")); }));
    EXPECT_EQ(params->invalidNames(), QStringList{QStringLiteral("spno2.speed")})
        << "280 r/min does not suit a DBU400";
    EXPECT_TRUE(window->drives()->variantDeclined(2));
    // Not asked again while connected.
    bool asked = false;
    whenModal(isVariantQuestion, [&asked](QWidget* w) {
        asked = true;
        qobject_cast<QMessageBox*>(w)->reject();
    });
    speed->enter(QStringLiteral("300"));
    QTest::qWait(200);
    EXPECT_FALSE(asked);
    EXPECT_TRUE(params->invalidNames().isEmpty());
}

TEST_F(MainWindowMachinesTest, EachFamilyShowsItsOwnAddressSwitches)
{
    BusListModel* model = window->busPanel()->model();
    auto cell = [&](int slave) {
        return model->index(model->rowOf(slave), BusListModel::Switches).data().toString();
    };
    EXPECT_EQ(cell(150), QStringLiteral("SW1=9 SW2=6"));
    EXPECT_EQ(cell(7), QStringLiteral("DIP ON: 1,2,3"));
    const QString tip =
        model->headerData(BusListModel::Switches, Qt::Horizontal, Qt::ToolTipRole).toString();
    EXPECT_TRUE(tip.contains(QStringLiteral("rotary switches SW1 and SW2"))) << qPrintable(tip);
    EXPECT_TRUE(tip.contains(QStringLiteral("DIP switches 1–7"))) << qPrintable(tip);
    // The page header of the DC controller names its switches too.
    select({7});
    ASSERT_TRUE(waitFor([&] {
        return window->workspace()->titleText().contains(QStringLiteral("DIP ON: 1,2,3"));
    })) << qPrintable(window->workspace()->titleText());
    // Add drive says how each family sets the number (a window-modal dialog that does not
    // block: read when it shows).
    for (QPushButton* b : window->busPanel()->findChildren<QPushButton*>()) {
        if (b->text() == QStringLiteral("A&dd drive…"))
            b->click();
    }
    QDialog* dialog = nullptr;
    ASSERT_TRUE(waitFor([&] {
        dialog = window->findChild<QDialog*>(QStringLiteral("driveLineDialog"));
        return dialog && dialog->isVisible();
    }));
    auto* help = dialog->findChild<QLabel*>(QStringLiteral("switchHelp"));
    ASSERT_NE(help, nullptr);
    const QString label = help->text();
    dialog->reject();
    EXPECT_TRUE(label.contains(QStringLiteral("SW1 and SW2"))) << qPrintable(label);
    EXPECT_TRUE(label.contains(QStringLiteral("DIP switches 1–7"))) << qPrintable(label);
}

TEST_F(MainWindowMachinesTest, AMachineNamedInTheBusListIsNamedEverywhereAndKeptForTheBus)
{
    // F2 on the bus list's row, a name refused first (a control character), then a good one.
    select({1});
    QTableView* view = window->busPanel()->view();
    view->setCurrentIndex(
        window->busPanel()->model()->index(window->busPanel()->model()->rowOf(1), 0));
    int asked = 0;
    QString refusal;
    std::function<void(QWidget*)> answer = [&](QWidget* w) {
        auto* dialog = qobject_cast<QInputDialog*>(w);
        ++asked;
        if (asked == 1) {
            dialog->setTextValue(QStringLiteral("Infeed\x07"));
        } else {
            refusal = dialog->labelText();
            dialog->setTextValue(QStringLiteral("Infeed conveyor 3"));
        }
        dialog->accept();
        if (asked == 1)
            whenModal([](QWidget* x) { return qobject_cast<QInputDialog*>(x) != nullptr; }, answer);
    };
    whenModal([](QWidget* w) { return qobject_cast<QInputDialog*>(w) != nullptr; }, answer);
    QAction* name = nullptr;
    for (QAction* a : view->actions())
        name = a->shortcut() == QKeySequence(Qt::Key_F2) ? a : name;
    ASSERT_NE(name, nullptr) << "F2 names the machine of the current row";
    name->trigger();
    ASSERT_TRUE(waitFor([&] { return !window->drives()->name(1).isEmpty(); }));
    EXPECT_EQ(asked, 2);
    EXPECT_TRUE(refusal.contains(QStringLiteral("control characters"))) << qPrintable(refusal);
    EXPECT_EQ(window->drives()->name(1), QStringLiteral("Infeed conveyor 3"));

    // The bus list, the page header and the Test run page.
    BusListModel* model = window->busPanel()->model();
    EXPECT_EQ(model->index(model->rowOf(1), BusListModel::Name).data().toString(),
              QStringLiteral("Infeed conveyor 3"));
    EXPECT_TRUE(window->workspace()->titleText().startsWith(
        QStringLiteral("Machine number 1 (Infeed conveyor 3)")))
        << qPrintable(window->workspace()->titleText());
    // The start question names it.
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    TestRunPanel* panel = testRun(1);
    ASSERT_NE(panel, nullptr);
    ASSERT_TRUE(waitFor([&] { return panel->commandsEnabled(); }));
    const QString start = startQuestion(panel);
    EXPECT_TRUE(start.contains(QStringLiteral("machine number 1 (Infeed conveyor 3)")))
        << qPrintable(start);

    // A backup carries it.
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("named.json"));
    auto* backup = new BackupDialog(window->drives(), ConnectionSettings(), window.get());
    bool saved = false;
    QObject::connect(backup, &BackupDialog::backupFinished, [&](bool ok) { saved = ok; });
    backup->show();
    backup->startBackup({1}, file);
    ASSERT_TRUE(waitFor([&] { return saved; }, 30000));
    QFile f(file);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_EQ(QJsonDocument::fromJson(f.readAll())
                  .object()
                  .value(QStringLiteral("devices"))
                  .toArray()
                  .at(0)
                  .toObject()
                  .value(QStringLiteral("machineName"))
                  .toString(),
              QStringLiteral("Infeed conveyor 3"));
    backup->close();

    // Kept for this bus: after a restart of the program it is there again.
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.simSpec = QStringLiteral("dbu200@1,dbu200@2,dbu400@150,dcpid@7");
    EXPECT_EQ(BusMemory::names(BusMemory::key(settings)).value(1),
              QStringLiteral("Infeed conveyor 3"));
    window.reset();
    window = std::make_unique<MainWindow>(
        [this](const ConnectionSettings& s, TrafficLog* log, QString* error) {
            auto made = BackendFactory::makeClient(s, log);
            bus = made.simBus;
            if (error)
                *error = made.error;
            return std::move(made.client);
        });
    window->show();
    settings.timeoutMs = 100;
    window->connectTo(settings, {{1, QStringLiteral("dbu200")}});
    ASSERT_TRUE(
        waitFor([&] { return window->drives() && window->drives()->slaves().size() == 1; }));
    EXPECT_EQ(window->drives()->name(1), QStringLiteral("Infeed conveyor 3"));
    EXPECT_EQ(window->drives()->session(1)->machineName(), QStringLiteral("Infeed conveyor 3"));
}
