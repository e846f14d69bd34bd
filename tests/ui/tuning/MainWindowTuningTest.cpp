// The Speed loop tuning page in the real window against the simulated DC controller (dcpid@7):
// only for drives whose profile can be tuned, a step test with its metrics, the relay autotune's
// proposal, Accept (writes it, then the check: a step test compared with the prediction), Reject
// (the old gains back), Store (asks first, Reject the default, when the check failed), and a
// relay refused on a 19200 bit/s line with wire timing, saying what to change.
#include "tests/ui/main/MainWindowFixture.h"

#include "sim/SimBackend.h"
#include "ui/tuning/ProposalFlow.h"

#include "ui/tuning/AutotunePanel.h"
#include "ui/tuning/StepTestPanel.h"
#include "ui/tuning/TuningChart.h"
#include "ui/tuning/TuningGains.h"
#include "ui/tuning/TuningPage.h"
#include "ui/tuning/TuningRunCsv.h"
#include "ui/tuning/TuningRunList.h"
#include "ui/tuning/TuningRunsView.h"

#include <QLineEdit>
#include <QTemporaryDir>

#include <cmath>

using MainWindowTuningTest = opentop::test::MainWindowFixture;

namespace opentop::test {
namespace {

TuningPage* tuningPageOf(MainWindow& window, int slave)
{
    if (window.workspace()->drive() != window.drives()->parameters(slave))
        return nullptr;
    QTabWidget* tabs = window.workspace()->tabs();
    for (int i = 0; i < tabs->count(); ++i) {
        if (auto* page = qobject_cast<TuningPage*>(tabs->widget(i))) {
            tabs->setCurrentIndex(i);
            return page;
        }
    }
    return nullptr;
}

// Answers the confirmation that shows with Yes (or Cancel); returns its text.
QString answer(QMessageBox::StandardButton button)
{
    QMessageBox* box = nullptr;
    waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box != nullptr;
    });
    if (!box)
        return QString();
    const QString text = box->text();
    box->button(button)->click();
    return text;
}

bool near(double a, double b)
{
    return std::abs(a - b) <= 1e-3 * std::max(1.0, std::abs(b));
}

// The gains in the (simulated) drive, read over the bus.
std::optional<PidGains> driveGains(MainWindow& window, int slave, const TuningSpec& spec)
{
    TuningRunner probe(window.drives()->session(slave), spec);
    std::optional<PidGains> gains;
    bool done = false;
    probe.readGains([&](bool ok, const PidGains& g, const QString&) {
        if (ok)
            gains = g;
        done = true;
    });
    waitFor([&] { return done; });
    return gains;
}

class TuningPageTest : public MainWindowFixture
{
protected:
    // Autotune at `speed` 1/s, confirmed; true when it proposed gains.
    bool autotune(int speed = 300)
    {
        page->showAutotune();
        AutotunePanel* panel = page->autotunePanel();
        panel->findChild<QLineEdit*>(QStringLiteral("autotuneSpeed"))
            ->setText(QString::number(speed));
        panel->findChild<QPushButton*>(QStringLiteral("autotune"))->click();
        if (answer(QMessageBox::Yes).isEmpty() || !waitFor([&] { return page->isBusy(); }) ||
            !idle(90000))
            return false;
        return !panel->proposalText().isEmpty();
    }
    // Accept; while the step test's question shows, the motor is coupled to another load (a
    // longer speed gate, a faster motor), then the question is answered. True once the check
    // ran.
    bool acceptOnAChangedPlant()
    {
        button("accept")->click();
        QMessageBox* question = nullptr;
        if (!waitFor([&] {
                return (question = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()));
            }))
            return false;
        bus->control(7, {QStringLiteral("motor"), QStringLiteral("gate=100"),
                         QStringLiteral("no_load=2000")});
        question->button(QMessageBox::Yes)->click();
        return waitFor([&] { return page->runs().size() == 2; }) && idle();
    }
    QPushButton* button(const char* name)
    {
        return page->autotunePanel()->findChild<QPushButton*>(QLatin1String(name));
    }

    void SetUp() override
    {
        MainWindowFixture::SetUp();
        // The speed loop (commutation frequency) is the closed-loop mode tests step in.
        bus->control(7, {QStringLiteral("set"), QStringLiteral("0x0080"), QStringLiteral("2")});
        select({7});
        ASSERT_TRUE(waitFor([&] { return (page = tuningPageOf(*window, 7)) != nullptr; }));
        QString error;
        spec = *TuningSpec::of(window->drives()->session(7)->profile(), &error);
        ASSERT_TRUE(waitFor([&] { return page->gains()->present().has_value(); }));
    }

    bool idle(int ms = 40000)
    {
        return waitFor([&] { return !page->isBusy(); }, ms);
    }

    TuningPage* page = nullptr;
    TuningSpec spec;
};

} // namespace
} // namespace opentop::test

using namespace opentop::test;

TEST_F(MainWindowTuningTest, TheTuningPageIsThereForTheDcControllerOnly)
{
    select({7});
    EXPECT_TRUE(waitFor([&] { return tuningPageOf(*window, 7) != nullptr; }));
    select({1});
    ASSERT_TRUE(
        waitFor([&] { return window->workspace()->drive() == window->drives()->parameters(1); }));
    EXPECT_EQ(tuningPageOf(*window, 1), nullptr);
}

TEST_F(TuningPageTest, AStepTestAsksFirstThenShowsARunWithItsMetrics)
{
    page->stepPanel()->setStep(0, 300);
    page->stepPanel()->findChild<QPushButton*>(QStringLiteral("runStep"))->click();
    const QString question = answer(QMessageBox::Yes);
    EXPECT_TRUE(question.contains(QStringLiteral("The motor of drive 7 (DCPID-20A)")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("from 0 to 300 1/s"))) << qPrintable(question);
    ASSERT_TRUE(waitFor([&] { return page->isBusy(); }));
    ASSERT_TRUE(idle());
    ASSERT_EQ(page->runs().size(), 1);
    const TuningRun& run = page->runs().first();
    EXPECT_TRUE(run.result.ok) << qPrintable(run.result.error);
    ASSERT_TRUE(run.result.metrics.valid) << qPrintable(run.result.metrics.error);
    EXPECT_TRUE(run.result.metrics.riseMs.has_value());
    EXPECT_GT(run.result.metrics.peakCurrent, 0);
    EXPECT_EQ(run.result.speedUnit, QStringLiteral("1/s"));
    EXPECT_TRUE(run.result.stopConfirmed) << qPrintable(run.result.stopDetail);
    EXPECT_GE(page->runsView()->chart()->curveCount(), 3);
    EXPECT_TRUE(page->stopReport().contains(QStringLiteral("stopped")))
        << qPrintable(page->stopReport());
    // Saved with its gains and metrics in the header.
    QTemporaryDir dir;
    QString error;
    ASSERT_TRUE(page->runsView()->saveCsv(dir.filePath(QStringLiteral("run.csv")), &error))
        << qPrintable(error);
    const QString csv = TuningRunCsv::text(run, QStringLiteral("drive 7"));
    EXPECT_TRUE(csv.contains(QStringLiteral("# gains: P 0.1000"))) << qPrintable(csv.left(400));
    EXPECT_TRUE(csv.contains(QStringLiteral("# rise_time_ms: "))) << qPrintable(csv.left(400));
    EXPECT_TRUE(page->runsView()->savePng(dir.filePath(QStringLiteral("chart.png"))));
    // Nothing moves after the test.
    EXPECT_TRUE(waitFor([&] { return simRegister(7, 0x0040) == 0; }));
}

TEST_F(TuningPageTest, NothingMovesWhenTheQuestionIsCancelled)
{
    page->stepPanel()->findChild<QPushButton*>(QStringLiteral("runStep"))->click();
    EXPECT_FALSE(answer(QMessageBox::Cancel).isEmpty());
    QTest::qWait(300);
    EXPECT_FALSE(page->isBusy());
    EXPECT_TRUE(page->runs().isEmpty());
}

TEST_F(TuningPageTest, AutotuneProposesGainsAcceptWritesThemAndRejectRestoresTheOldOnes)
{
    const std::optional<PidGains> old = driveGains(*window, 7, spec);
    ASSERT_TRUE(old);
    page->showAutotune();
    AutotunePanel* panel = page->autotunePanel();
    panel->findChild<QLineEdit*>(QStringLiteral("autotuneSpeed"))->setText(QStringLiteral("300"));
    panel->findChild<QPushButton*>(QStringLiteral("autotune"))->click();
    const QString question = answer(QMessageBox::Yes);
    EXPECT_TRUE(question.contains(QStringLiteral("drive 7 (DCPID-20A)"))) << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("open loop"))) << qPrintable(question);
    ASSERT_TRUE(waitFor([&] { return page->isBusy(); }));
    ASSERT_TRUE(idle(60000));
    ASSERT_FALSE(panel->proposalText().isEmpty())
        << qPrintable(panel->resultText() + QLatin1Char('\n') + page->phaseText());
    EXPECT_TRUE(panel->resultText().contains(QStringLiteral("Ku")))
        << qPrintable(panel->resultText());
    EXPECT_TRUE(panel->resultText().contains(QStringLiteral("Tu")))
        << qPrintable(panel->resultText());
    ASSERT_EQ(page->runs().size(), 1);
    EXPECT_TRUE(page->runs().first().isPrediction());
    EXPECT_FALSE(page->runs().first().result.samples.isEmpty());
    const PidGains proposal = page->runs().first().gains;
    // The speed mode is the closed loop again, the motor stopped.
    EXPECT_EQ(simRegister(7, 0x0080), 2);
    // Accept: the proposal in the drive, then the step test the prediction shows.
    auto* accept = panel->findChild<QPushButton*>(QStringLiteral("accept"));
    auto* store = panel->findChild<QPushButton*>(QStringLiteral("store"));
    EXPECT_FALSE(store->isEnabled());
    ASSERT_TRUE(accept->isEnabled());
    accept->click();
    const QString step = answer(QMessageBox::Yes);
    EXPECT_TRUE(step.contains(QStringLiteral("from 150 to 300 1/s"))) << qPrintable(step);
    const std::optional<PidGains> written = driveGains(*window, 7, spec);
    ASSERT_TRUE(written);
    EXPECT_TRUE(near(written->p, proposal.p)) << written->p << " " << proposal.p;
    EXPECT_TRUE(near(written->i, proposal.i)) << written->i << " " << proposal.i;
    ASSERT_TRUE(waitFor([&] { return page->runs().size() == 2; }));
    ASSERT_TRUE(idle());
    const TuningRun& measured = page->runs().last();
    EXPECT_TRUE(measured.result.metrics.valid) << qPrintable(measured.result.error);
    EXPECT_TRUE(near(measured.gains.p, proposal.p));
    EXPECT_TRUE(store->isEnabled());
    // The check after Accept: the measured step as the prediction said.
    EXPECT_TRUE(panel->verdictText().contains(QStringLiteral("passed")))
        << qPrintable(panel->verdictText());
    // Reject: the gains the drive had before.
    panel->findChild<QPushButton*>(QStringLiteral("reject"))->click();
    ASSERT_TRUE(idle());
    const std::optional<PidGains> back = driveGains(*window, 7, spec);
    ASSERT_TRUE(back);
    EXPECT_TRUE(near(back->p, old->p)) << back->p << " " << old->p;
    EXPECT_TRUE(near(back->i, old->i)) << back->i << " " << old->i;
    EXPECT_TRUE(near(back->d, old->d));
    EXPECT_FALSE(store->isEnabled());
}

TEST_F(TuningPageTest, StopCancelsARunningStepTestAndTheMotorStops)
{
    page->stepPanel()->setStep(0, 400);
    page->stepPanel()
        ->findChild<QLineEdit*>(QStringLiteral("recordTime"))
        ->setText(QStringLiteral("10000"));
    page->stepPanel()->findChild<QPushButton*>(QStringLiteral("runStep"))->click();
    answer(QMessageBox::Yes);
    ASSERT_TRUE(waitFor([&] { return simRegister(7, 0x0040) > 0; }));
    page->findChild<QPushButton*>(QStringLiteral("tuningStop"))->click();
    ASSERT_TRUE(idle());
    ASSERT_EQ(page->runs().size(), 1);
    EXPECT_TRUE(page->runs().first().result.aborted);
    EXPECT_TRUE(page->runs().first().result.stopConfirmed);
    EXPECT_EQ(simRegister(7, 0x0040), 0);
}

// The plant changes after the autotune (the motor coupled to another load): the check after
// Accept fails and says what it measured; Store then asks, with Reject as the default answer,
// and Reject writes back the gains the drive had.
TEST_F(TuningPageTest, AFailedCheckMakesStoreAskWithRejectAsTheDefault)
{
    const std::optional<PidGains> old = driveGains(*window, 7, spec);
    ASSERT_TRUE(old);
    ASSERT_TRUE(autotune()) << qPrintable(page->autotunePanel()->resultText());
    ASSERT_TRUE(acceptOnAChangedPlant());
    const QString verdict = page->autotunePanel()->verdictText();
    EXPECT_TRUE(verdict.contains(QStringLiteral("FAILED"))) << qPrintable(verdict);
    EXPECT_TRUE(page->phaseText().contains(QStringLiteral("failed the check")))
        << qPrintable(page->phaseText());
    ASSERT_TRUE(button("store")->isEnabled());
    button("store")->click();
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box && box->objectName() == QLatin1String("storeQuestion");
    }));
    EXPECT_TRUE(box->text().contains(QStringLiteral("drive 7 (DCPID-20A)")))
        << qPrintable(box->text());
    EXPECT_TRUE(box->text().contains(QStringLiteral("Check failed"))) << qPrintable(box->text());
    ASSERT_EQ(box->defaultButton(), box->button(QMessageBox::No));
    EXPECT_EQ(box->defaultButton()->text(), QStringLiteral("Reject the gains"));
    QTest::keyClick(box, Qt::Key_Return);
    ASSERT_TRUE(idle());
    const std::optional<PidGains> back = driveGains(*window, 7, spec);
    ASSERT_TRUE(back);
    EXPECT_TRUE(near(back->p, old->p)) << back->p << " " << old->p;
    EXPECT_TRUE(near(back->i, old->i));
    EXPECT_FALSE(button("store")->isEnabled());
    // Nothing was stored: a power cycle brings back the factory gains.
    bus->control(7, {QStringLiteral("power-cycle")});
    const std::optional<PidGains> stored = driveGains(*window, 7, spec);
    ASSERT_TRUE(stored);
    EXPECT_TRUE(near(stored->p, 0.1)) << stored->p;
}

// The same failed check, and the user insists: Store anyway stores the gains, as asked.
TEST_F(TuningPageTest, StoreAnywayAfterAFailedCheckStoresTheGains)
{
    ASSERT_TRUE(autotune());
    const PidGains proposal = page->runs().first().gains;
    ASSERT_TRUE(acceptOnAChangedPlant());
    ASSERT_TRUE(page->autotunePanel()->verdictText().contains(QStringLiteral("FAILED")));
    button("store")->click();
    const QString text = answer(QMessageBox::Yes); // "Store anyway"
    EXPECT_TRUE(text.contains(QStringLiteral("did not pass the check"))) << qPrintable(text);
    ASSERT_TRUE(idle());
    EXPECT_TRUE(page->phaseText().contains(QStringLiteral("stored")))
        << qPrintable(page->phaseText());
    bus->control(7, {QStringLiteral("power-cycle")});
    const std::optional<PidGains> stored = driveGains(*window, 7, spec);
    ASSERT_TRUE(stored);
    EXPECT_TRUE(near(stored->p, proposal.p)) << stored->p << " " << proposal.p;
}

namespace opentop::test {
namespace {

// The window on a 19200 bit/s line whose frames take their wire time, every drive polled.
class SlowLineTuningTest : public TuningPageTest
{
protected:
    std::unique_ptr<ModbusClient> makeClient(const ConnectionSettings& s, TrafficLog* log,
                                             QString* error) override
    {
        bus = SimBus::fromSpec(s.simSpec, error);
        if (!bus)
            return nullptr;
        auto backend = std::make_unique<SimBackend>(bus, true, 19200);
        backend->setTrafficLog(log);
        return std::make_unique<ModbusClient>(std::move(backend), s);
    }
};

} // namespace
} // namespace opentop::test

// The case: 300 1/s, 10 %, medium at 19200 bit/s with the other drives polled. The
// relay's period holds too few readings: refused, with why and what to change; nothing to
// accept; the motor stopped and the closed loop back.
TEST_F(SlowLineTuningTest, ARelayTheBusCannotResolveIsRefusedWithWhatToChange)
{
    EXPECT_FALSE(autotune());
    const QString text = page->autotunePanel()->resultText();
    EXPECT_TRUE(text.contains(QStringLiteral("Autotune failed"))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("readings"))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("What to change: Raise the line rate")))
        << qPrintable(text);
    EXPECT_TRUE(page->phaseText().contains(QStringLiteral("refused")))
        << qPrintable(page->phaseText());
    EXPECT_FALSE(button("accept")->isEnabled());
    EXPECT_TRUE(page->runs().isEmpty()); // no prediction to compare with
    EXPECT_TRUE(page->stopReport().contains(QStringLiteral("stopped")))
        << qPrintable(page->stopReport());
    EXPECT_EQ(simRegister(7, 0x0080), 2);
    EXPECT_TRUE(waitFor([&] { return simRegister(7, 0x0012) == 0; }));
}
