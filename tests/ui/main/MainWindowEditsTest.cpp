// Edits through the real window: a page with a field not accepted writes nothing and says why
// at the field; user-facing text names parameters by label; the speed display's roller
// diameter in millimetres and its preview as the panel shows it; parameter initialisation.
#include "tests/ui/main/MainWindowFixture.h"

#include "model/monitor/DeviceMonitor.h"
#include "model/monitor/PanelMirror.h"
#include "model/profile/SpeedDisplay.h"
#include "ui/pages/RunningDataPage.h"
#include "ui/pages/SpeedUnitsPage.h"
#include "ui/workspace/ParameterInitBox.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QGroupBox>
#include <QLineEdit>

using namespace opentop;
using namespace opentop::test;

namespace {

using MainWindowEditsTest = opentop::test::MainWindowFixture;

template <typename Page = ParameterPage>
Page* pageWith(DriveWorkspace* workspace, const QString& parameter)
{
    for (int i = 0; i < workspace->tabs()->count(); ++i) {
        auto* page = qobject_cast<Page*>(workspace->tabs()->widget(i));
        if (page && page->parameterNames().contains(parameter))
            return page;
    }
    return nullptr;
}

ParameterField* fieldOf(QWidget* page, const QString& parameter)
{
    for (ParameterField* f : page->findChildren<ParameterField*>()) {
        if (f->parameterName() == parameter)
            return f;
    }
    return nullptr;
}

int writeFramesTo(TrafficLog* log, int slave)
{
    int n = 0;
    for (const TrafficEntry& e : log->entries()) {
        if (e.direction == TrafficEntry::Direction::Tx && e.slave == slave &&
            (e.function == 6 || e.function == 16))
            ++n;
    }
    return n;
}

// Every text a user can read on `root`: labels, buttons, group titles, drop-down items,
// line edits, tab titles and tooltips.
QStringList visibleTexts(QWidget* root)
{
    QStringList texts;
    for (QWidget* w : root->findChildren<QWidget*>()) {
        if (!w->isVisibleTo(root))
            continue;
        if (!w->toolTip().isEmpty())
            texts << w->toolTip();
        if (auto* l = qobject_cast<QLabel*>(w))
            texts << l->text();
        else if (auto* b = qobject_cast<QAbstractButton*>(w))
            texts << b->text();
        else if (auto* g = qobject_cast<QGroupBox*>(w))
            texts << g->title();
        else if (auto* e = qobject_cast<QLineEdit*>(w))
            texts << e->text() << e->placeholderText();
        else if (auto* c = qobject_cast<QComboBox*>(w)) {
            for (int i = 0; i < c->count(); ++i)
                texts << c->itemText(i);
        } else if (auto* t = qobject_cast<QTabWidget*>(w)) {
            for (int i = 0; i < t->count(); ++i)
                texts << t->tabText(i);
        }
    }
    return texts;
}

} // namespace

TEST_F(MainWindowEditsTest, APageWithAFieldNotAcceptedWritesNothingAndSaysWhyAtTheField)
{
    select({1});
    DriveWorkspace* workspace = window->workspace();
    DeviceParameters* params = window->drives()->parameters(1);
    ASSERT_TRUE(waitFor([&] { return workspace->drive() == params; }));
    ASSERT_TRUE(waitFor([&] {
        return params->entry(QStringLiteral("spno2.speed"))->device.valid &&
               params->entry(QStringLiteral("spno2.accel"))->device.valid;
    }));
    ParameterPage* page = pageWith(workspace, QStringLiteral("spno2.speed"));
    ASSERT_NE(page, nullptr);
    workspace->tabs()->setCurrentWidget(page);
    ParameterField* speed = fieldOf(page, QStringLiteral("spno2.speed"));
    ParameterField* accel = fieldOf(page, QStringLiteral("spno2.accel"));
    ASSERT_TRUE(speed && accel);
    const int speedBefore = simRegister(1, 0xCA03);
    const int accelBefore = simRegister(1, 0x1303);
    const QString accelText = accelBefore == 45 ? QStringLiteral("5.5") : QStringLiteral("4.5");

    accel->enter(accelText);              // accepted
    speed->enter(QStringLiteral("5000")); // above the 3000 r/min the drive takes
    EXPECT_TRUE(accel->problem().isEmpty()) << qPrintable(accel->problem());
    EXPECT_FALSE(speed->problem().isEmpty());
    // In words, not only in its tooltip: the allowed range with its unit. The running data grid
    // says it on its message line under the grid (issue 24: under the field it moved the rows).
    auto* grid = qobject_cast<RunningDataPage*>(page);
    ASSERT_NE(grid, nullptr);
    const QString speedLabel = params->entry(QStringLiteral("spno2.speed"))->meta->label;
    EXPECT_TRUE(speed->messageText().contains(QStringLiteral("250–3000 r/min")))
        << qPrintable(speed->messageText());
    EXPECT_FALSE(speed->messageText().contains(QStringLiteral("spno2")));
    EXPECT_FALSE(speed->messageLabel()->isVisible());
    EXPECT_TRUE(grid->fieldMessages().startsWith(speedLabel + QStringLiteral(": Not accepted")))
        << qPrintable(grid->fieldMessages());
    EXPECT_FALSE(
        grid->fieldMessages().contains(params->entry(QStringLiteral("spno2.accel"))->meta->label));
    // The refused text stays in the field, as an edit that can be reverted.
    auto* speedEdit = qobject_cast<QLineEdit*>(speed->editor());
    ASSERT_NE(speedEdit, nullptr);
    EXPECT_EQ(speedEdit->text(), QStringLiteral("5000"));
    EXPECT_TRUE(params->pendingNames().contains(QStringLiteral("spno2.speed")));

    const int writesBefore = writeFramesTo(window->trafficLog(), 1);
    page->writePage();
    QTest::qWait(300);
    EXPECT_EQ(writeFramesTo(window->trafficLog(), 1), writesBefore); // no frame at all
    EXPECT_EQ(simRegister(1, 0xCA03), speedBefore);
    EXPECT_EQ(simRegister(1, 0x1303), accelBefore); // not the valid field either
    // The summary names the field by its label and says why.
    const QString status = page->statusText();
    EXPECT_TRUE(status.contains(QStringLiteral("Nothing was written"))) << qPrintable(status);
    EXPECT_TRUE(status.contains(params->entry(QStringLiteral("spno2.speed"))->meta->label))
        << qPrintable(status);
    EXPECT_TRUE(status.contains(QStringLiteral("250–3000 r/min"))) << qPrintable(status);
    EXPECT_FALSE(status.contains(QStringLiteral("spno2."))) << qPrintable(status);
    // Write all pending is held back the same way.
    workspace->writeAll();
    QTest::qWait(300);
    EXPECT_EQ(writeFramesTo(window->trafficLog(), 1), writesBefore);

    // Revert brings the drive's value back, without a red frame or message.
    page->revertPage();
    EXPECT_FALSE(params->hasPending());
    EXPECT_EQ(speedEdit->text(), QString::number(speedBefore));
    EXPECT_TRUE(speed->problem().isEmpty());
    EXPECT_TRUE(grid->fieldMessages().isEmpty()) << qPrintable(grid->fieldMessages());
    EXPECT_TRUE(speedEdit->styleSheet().isEmpty()) << qPrintable(speedEdit->styleSheet());

    // Typed but not confirmed, then Re-read: the valid value read has no red frame.
    speedEdit->setText(QStringLiteral("9999"));
    emit speedEdit->textEdited(speedEdit->text());
    EXPECT_FALSE(speedEdit->styleSheet().isEmpty());
    speedEdit->setModified(false);
    bool reread = false;
    QObject::connect(page, &ParameterPage::operationFinished, page, [&] { reread = true; });
    page->refresh();
    ASSERT_TRUE(waitFor([&] { return reread; }));
    EXPECT_EQ(speedEdit->text(), QString::number(speedBefore));
    EXPECT_TRUE(speedEdit->styleSheet().isEmpty()) << qPrintable(speedEdit->styleSheet());
    EXPECT_TRUE(grid->fieldMessages().isEmpty()) << qPrintable(grid->fieldMessages());

    // Corrected, the page is written.
    speed->enter(QStringLiteral("2200"));
    accel->enter(accelText);
    reread = false;
    page->writePage();
    ASSERT_TRUE(waitFor([&] { return reread && !params->hasPending(); }));
    EXPECT_EQ(simRegister(1, 0xCA03), 2200);
}

TEST_F(MainWindowEditsTest, NoPageShowsAnInternalParameterName)
{
    QStringList names;
    for (const Profile& profile : ProfileRegistry::builtIn().profiles()) {
        for (const ParameterMeta& m : profile.parameters)
            names << m.name;
    }
    ASSERT_FALSE(names.isEmpty());
    for (int slave : {1, 7}) {
        SCOPED_TRACE(slave);
        select({slave});
        DriveWorkspace* workspace = window->workspace();
        DeviceParameters* params = window->drives()->parameters(slave);
        ASSERT_TRUE(waitFor([&] { return workspace->drive() == params; }));
        bool read = false;
        QObject::connect(workspace, &DriveWorkspace::operationFinished, workspace,
                         [&] { read = true; });
        workspace->refreshAll();
        ASSERT_TRUE(waitFor([&] { return read; }));
        for (int i = 0; i < workspace->tabs()->count(); ++i) {
            QWidget* page = workspace->tabs()->widget(i);
            workspace->tabs()->setCurrentIndex(i);
            QTest::qWait(300); // pages that read when shown have answered
            // A refused edit on the page shows its message too.
            for (ParameterField* f : page->findChildren<ParameterField*>()) {
                if (auto* edit = qobject_cast<QLineEdit*>(f->editor());
                    edit && !edit->isReadOnly() && f->isEnabled()) {
                    f->enter(QStringLiteral("999999"));
                    break;
                }
            }
            auto* p = qobject_cast<ParameterPage*>(page);
            if (p && !params->invalidNames().isEmpty())
                p->writePage(); // refused: the summary is shown
            QTest::qWait(50);
            for (const QString& text : visibleTexts(page)) {
                for (const QString& name : names)
                    EXPECT_FALSE(text.contains(name))
                        << qPrintable(workspace->tabs()->tabText(i)) << ": \"" << qPrintable(name)
                        << "\" in " << qPrintable(text);
            }
            params->revertAll();
        }
    }
}

TEST_F(MainWindowEditsTest, AFiftyMillimetreRollerIsTakenAndThePreviewShowsWhatThePanelShows)
{
    select({1});
    DriveWorkspace* workspace = window->workspace();
    DeviceParameters* params = window->drives()->parameters(1);
    ASSERT_TRUE(waitFor([&] { return workspace->drive() == params; }));
    ASSERT_TRUE(waitFor(
        [&] { return params->entry(QStringLiteral("unit.diameter_meter"))->device.valid; }));
    auto* page = pageWith<SpeedUnitsPage>(workspace, QStringLiteral("unit.diameter_meter"));
    ASSERT_NE(page, nullptr);
    workspace->tabs()->setCurrentWidget(page);
    ParameterField* diameter = page->field(QStringLiteral("unit.diameter_meter"));
    ASSERT_NE(diameter, nullptr);
    // The unit is shown at the field.
    bool mm = false;
    for (QLabel* l : diameter->findChildren<QLabel*>())
        mm = mm || (l->isVisible() && l->text() == QStringLiteral("mm"));
    EXPECT_TRUE(mm);

    page->field(QStringLiteral("unit.mode"))->enter(QStringLiteral("2")); // m/min
    page->field(QStringLiteral("unit.decimals"))->enter(QStringLiteral("3"));
    page->field(QStringLiteral("unit.reduction"))->enter(QStringLiteral("1.00"));
    page->field(QStringLiteral("unit.increase"))->enter(QStringLiteral("1.00"));
    diameter->enter(QStringLiteral("50"));
    EXPECT_TRUE(diameter->problem().isEmpty()) << qPrintable(diameter->problem());
    EXPECT_TRUE(params->invalidNames().isEmpty());
    bool written = false;
    QObject::connect(page, &ParameterPage::operationFinished, page, [&] { written = true; });
    page->writePage();
    ASSERT_TRUE(waitFor([&] { return written && !params->hasPending(); }))
        << qPrintable(page->statusText());
    EXPECT_EQ(simRegister(1, 0x040F), 500); // 50.0 mm in steps of 0.1 mm
    EXPECT_EQ(simRegister(1, 0x0409), 2);

    // 100 mm at 1500 r/min: 471.239 m/min, shown as the 5-digit panel shows it.
    diameter->enter(QStringLiteral("100"));
    page->setPreviewSpeed(1500);
    EXPECT_EQ(page->previewUnit(), QStringLiteral("m/min"));
    EXPECT_EQ(page->previewText(), QStringLiteral("471.23"));
    // The monitor's panel mirror shows the same for the same speed display.
    SpeedDisplay::Settings settings;
    settings.mode = SpeedDisplay::Mode::LinearMeter;
    settings.decimals = 3;
    settings.diameterMeter = 100;
    MonitorSample sample;
    sample.slave = 1;
    sample.currentShown = SpeedDisplay(settings).show(1500);
    const Profile* dbu = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    ASSERT_NE(dbu, nullptr);
    EXPECT_EQ(PanelMirror::show(*dbu, sample, PanelMirror::Content::Speed, {}).text,
              page->previewText());

    // r/min with 3 decimals: 1350.0 on the panel, as the mirror shows it, not 1350.000.
    page->field(QStringLiteral("unit.mode"))->enter(QStringLiteral("0"));
    page->setPreviewSpeed(1350);
    EXPECT_EQ(page->previewText(), QStringLiteral("1350.0"));
    settings.mode = SpeedDisplay::Mode::Rpm;
    sample.currentShown = SpeedDisplay(settings).show(1350);
    EXPECT_EQ(PanelMirror::show(*dbu, sample, PanelMirror::Content::Speed, {}).text,
              page->previewText());
}

TEST_F(MainWindowEditsTest, ParameterInitialisationNamesTheDriveSpellsOutWhatChangesAndReReads)
{
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("2200")});
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x1021"), QStringLiteral("4")});
    select({1});
    DriveWorkspace* workspace = window->workspace();
    DeviceParameters* params = window->drives()->parameters(1);
    ASSERT_TRUE(waitFor([&] { return workspace->drive() == params; }));
    ASSERT_TRUE(waitFor([&] {
        const auto* e = params->entry(QStringLiteral("spno2.speed"));
        return e->device.valid && e->device.number == 2200;
    }));
    ParameterPage* page = pageWith(workspace, QStringLiteral("comm.rate"));
    ASSERT_NE(page, nullptr);
    workspace->tabs()->setCurrentWidget(page);
    auto* init = page->findChild<ParameterInitBox*>();
    ASSERT_NE(init, nullptr);
    EXPECT_TRUE(init->isVisible());
    EXPECT_TRUE(init->button()->text().contains(QStringLiteral("drive 1")));

    // Cancel sends nothing.
    bool finished = false;
    QObject::connect(init, &ParameterInitBox::finished, init, [&] { finished = true; });
    const int writesBefore = writeFramesTo(window->trafficLog(), 1);
    init->start();
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box != nullptr;
    }));
    const QString text = box->text() + QLatin1Char('\n') + box->informativeText();
    EXPECT_TRUE(text.contains(QStringLiteral("drive 1"))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("Communication rate goes from 38400 bit/s")))
        << qPrintable(text);
    EXPECT_TRUE(
        text.contains(QStringLiteral("The link to the drive is lost from its next power-up")))
        << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("then reconnect at 19200 bit/s"))) << qPrintable(text);
    EXPECT_FALSE(text.contains(QStringLiteral("comm.rate"))) << qPrintable(text);
    EXPECT_EQ(box->standardButton(box->defaultButton()), QMessageBox::Cancel);
    box->button(QMessageBox::Cancel)->click();
    ASSERT_TRUE(waitFor([&] { return finished; }));
    EXPECT_EQ(writeFramesTo(window->trafficLog(), 1), writesBefore);
    EXPECT_EQ(simRegister(1, 0xCA03), 2200);

    // Confirmed: sent, then every value is read again.
    finished = false;
    init->start();
    box = nullptr;
    ASSERT_TRUE(waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box != nullptr;
    }));
    box->button(QMessageBox::Yes)->click();
    ASSERT_TRUE(waitFor([&] { return finished; }, 20000));
    EXPECT_TRUE(init->statusText().contains(QStringLiteral("initialised")))
        << qPrintable(init->statusText());
    EXPECT_EQ(simRegister(1, 0xCA03), 1000);
    EXPECT_EQ(simRegister(1, 0x1021), 2);
    EXPECT_EQ(params->entry(QStringLiteral("spno2.speed"))->device.number, 1000);
    EXPECT_EQ(params->entry(QStringLiteral("comm.rate"))->device.raw, 2);
}

TEST_F(MainWindowEditsTest, ParameterInitialisationIsRefusedWhileTheMotorRuns)
{
    select({1});
    DriveWorkspace* workspace = window->workspace();
    DeviceParameters* params = window->drives()->parameters(1);
    ASSERT_TRUE(waitFor([&] { return workspace->drive() == params; }));
    startDrive(1);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0; }));
    ParameterPage* page = pageWith(workspace, QStringLiteral("comm.rate"));
    ASSERT_NE(page, nullptr);
    auto* init = page->findChild<ParameterInitBox*>();
    ASSERT_NE(init, nullptr);
    bool finished = false;
    QObject::connect(init, &ParameterInitBox::finished, init, [&] { finished = true; });
    const int writesBefore = writeFramesTo(window->trafficLog(), 1);
    init->start();
    ASSERT_TRUE(waitFor([&] { return finished; }));
    EXPECT_EQ(QApplication::activeModalWidget(), nullptr);
    EXPECT_TRUE(init->statusText().contains(QStringLiteral("running")))
        << qPrintable(init->statusText());
    EXPECT_EQ(writeFramesTo(window->trafficLog(), 1), writesBefore);
    EXPECT_GT(speedOf(1), 0);
}

// A page behind another tab does not follow the monitor's values as they come (it would cost
// the program a tenth of a core at 16 drives): a value read while it is hidden is shown the
// moment the page comes into view, and its Write button still counts its edits meanwhile.
TEST_F(MainWindowEditsTest, AValueReadWhileThePageIsBehindAnotherTabShowsWhenItComesIntoView)
{
    select({1});
    DriveWorkspace* workspace = window->workspace();
    DeviceParameters* params = window->drives()->parameters(1);
    ASSERT_TRUE(waitFor([&] { return workspace->drive() == params; }));
    const QString name = QStringLiteral("spno2.speed");
    ASSERT_TRUE(waitFor([&] { return params->entry(name)->device.valid; }));
    ParameterPage* page = pageWith(workspace, name);
    ASSERT_NE(page, nullptr);
    ParameterField* field = fieldOf(page, name);
    auto* edit = qobject_cast<QLineEdit*>(field->editor());
    ASSERT_NE(edit, nullptr);
    workspace->tabs()->setCurrentWidget(page);
    ASSERT_TRUE(waitFor([&] { return page->isVisible(); }));
    const int before = simRegister(1, 0xCA03);
    const int changed = before == 1234 ? 1500 : 1234;

    // Behind another tab: the drive's value changes and is read.
    workspace->tabs()->setCurrentIndex(workspace->tabs()->indexOf(page) == 0 ? 1 : 0);
    ASSERT_TRUE(waitFor([&] { return !page->isVisible(); }));
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QString::number(changed)});
    bool read = false;
    params->refresh({name}, [&](int) { read = true; });
    ASSERT_TRUE(waitFor([&] { return read; }));
    EXPECT_EQ(edit->text(), QString::number(before)); // not followed while hidden

    workspace->tabs()->setCurrentWidget(page);
    ASSERT_TRUE(waitFor([&] { return page->isVisible(); }));
    EXPECT_EQ(edit->text(), QString::number(changed));
}
