// The station's results writer: the database on a thread of its own, so that a busy or distant
// database never makes the operator screen wait; jobs in order; nothing given is dropped.
#include "model/eol/ResultWriter.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultStore.h"
#include "model/eol/StationLease.h"
#include "tests/support/EolSampleUnit.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QTemporaryDir>
#include <QTimer>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

class ResultWriterTest : public ::testing::Test
{
protected:
    QString path() const { return dir.filePath(QStringLiteral("results.db")); }
    std::unique_ptr<ResultDatabase> open()
    {
        QString error;
        auto db = ResultDatabase::open(path(), &error);
        EXPECT_TRUE(db) << error.toStdString();
        return db;
    }
    // Runs the event loop until `done` or `ms`; the longest gap between two 10 ms ticks of a
    // timer meanwhile goes to *longestGapMs.
    static bool spinUntil(const std::function<bool()>& done, int ms, qint64* longestGapMs = nullptr)
    {
        QElapsedTimer clock;
        clock.start();
        qint64 last = 0;
        qint64 longest = 0;
        QTimer tick;
        QEventLoop loop;
        QObject::connect(&tick, &QTimer::timeout, &loop, [&] {
            longest = std::max(longest, clock.elapsed() - last);
            last = clock.elapsed();
            if (done() || clock.elapsed() > ms)
                loop.quit();
        });
        tick.start(10);
        loop.exec();
        if (longestGapMs)
            *longestGapMs = longest;
        return done();
    }

    QTemporaryDir dir;
};

} // namespace

TEST_F(ResultWriterTest, TheCallersThreadRunsOnWhileTheDatabaseIsBusy)
{
    ResultWriter writer;
    const ResultWriter::Opened opened = writer.openAndWait(path(), QStringLiteral("line 1"));
    ASSERT_TRUE(opened.ok) << qPrintable(opened.error);
    EXPECT_TRUE(writer.isOpen());
    EXPECT_TRUE(opened.displayText.contains(QStringLiteral("results.db")))
        << qPrintable(opened.displayText);

    // Another station holds SQLite's write lock: the writer waits for it (the busy timeout is
    // 10 s), and the caller's thread goes on meanwhile.
    auto other = open();
    QString error;
    ASSERT_TRUE(other->begin(&error)) << qPrintable(error);
    bool answered = false;
    UnitRecord begun;
    QString beginError;
    QObject context;
    writer.beginUnit(test::eolSampleUnit(QStringLiteral("SN-B1")), &context,
                     [&](const UnitRecord& record, const ResultWriter::Saved& saved) {
                         answered = true;
                         begun = record;
                         beginError = saved.error;
                     });
    EXPECT_FALSE(answered) << "never answered inside the call";
    qint64 longestGap = 0;
    EXPECT_FALSE(spinUntil([&] { return answered; }, 600, &longestGap));
    EXPECT_LT(longestGap, 200) << "the caller's event loop stood still";
    EXPECT_EQ(writer.pending(), 1);

    other->rollback();
    ASSERT_TRUE(spinUntil([&] { return answered; }, 12000));
    EXPECT_TRUE(beginError.isEmpty()) << qPrintable(beginError);
    EXPECT_FALSE(begun.id.isEmpty());
    EXPECT_EQ(writer.pending(), 0);
    const auto stored = ResultQueries(*other).load(begun.id, &error);
    ASSERT_TRUE(stored) << qPrintable(error);
    EXPECT_EQ(stored->status, UnitStatus::Running);
}

TEST_F(ResultWriterTest, DestroyedWithJobsGivenItFinishesThemFirst)
{
    UnitRecord record = test::eolSampleUnit(QStringLiteral("SN-D1"), UnitStatus::Pass);
    {
        ResultWriter writer;
        writer.open(path(), QStringLiteral("line 1"), nullptr, {});
        QObject context;
        // The begin's answer never comes (the writer goes first), so the finish is given the
        // id the test makes; what matters is that both are written before the writer is gone.
        record.id = QStringLiteral("00000000-0000-4000-8000-000000000001");
        record.started = QDateTime::currentDateTimeUtc();
        writer.beginUnit(record, &context, [](const UnitRecord&, const ResultWriter::Saved&) {});
        writer.finishUnit(record, &context, [](const ResultWriter::Saved&) {});
    }
    auto db = open();
    QString error;
    const auto stored = ResultQueries(*db).load(record.id, &error);
    ASSERT_TRUE(stored) << qPrintable(error);
    EXPECT_EQ(stored->status, UnitStatus::Pass);
    EXPECT_EQ(stored->measurements.size(), record.measurements.size());
}

TEST_F(ResultWriterTest, AnAnswerForAContextThatIsGoneIsDropped)
{
    ResultWriter writer;
    ASSERT_TRUE(writer.openAndWait(path(), QString()).ok);
    bool called = false;
    auto* context = new QObject;
    writer.beginUnit(test::eolSampleUnit(QStringLiteral("SN-G1")), context,
                     [&](const UnitRecord&, const ResultWriter::Saved&) { called = true; });
    delete context;
    ASSERT_TRUE(spinUntil([&] { return writer.pending() == 0; }, 5000));
    EXPECT_FALSE(called);
}

TEST_F(ResultWriterTest, ADatabaseThatCannotBeOpenedIsNamedAndNothingIsWritten)
{
    ResultWriter writer;
    const QString missing = dir.filePath(QStringLiteral("no/such/folder/results.db"));
    const ResultWriter::Opened opened = writer.openAndWait(missing, QString());
    EXPECT_FALSE(opened.ok);
    EXPECT_FALSE(writer.isOpen());
    EXPECT_TRUE(opened.error.contains(missing)) << qPrintable(opened.error);
    QString error;
    QObject context;
    bool answered = false;
    writer.beginUnit(test::eolSampleUnit(QStringLiteral("SN-N1")), &context,
                     [&](const UnitRecord&, const ResultWriter::Saved& saved) {
                         answered = true;
                         error = saved.error;
                     });
    ASSERT_TRUE(spinUntil([&] { return answered; }, 5000));
    EXPECT_FALSE(error.isEmpty());
}

TEST_F(ResultWriterTest, AUnitOfAProcessThatIsGoneIsInterruptedAndNamedAsTheStationOpens)
{
    QString legacyId;
    {
        auto db = open();
        QString error;
        // A process of this host that no longer exists left a unit running.
        StationLease gone(QStringLiteral("line 1"), QStringLiteral("opentop"));
        ASSERT_TRUE(gone.renew(*db, &error)) << qPrintable(error);
        ASSERT_TRUE(db->exec(QStringLiteral("UPDATE station_leases SET pid = 999999999"), &error));
        ResultStore store(*db);
        store.setLease(gone.id());
        UnitRecord left = test::eolSampleUnit(QStringLiteral("SN-L1"));
        left.station = QStringLiteral("line 1");
        ASSERT_TRUE(store.beginUnit(left, &error)) << qPrintable(error);
        // And a program from before leases left one too: judged by the station's name.
        UnitRecord old = test::eolSampleUnit(QStringLiteral("SN-L0"));
        old.station = QStringLiteral("line 1");
        ASSERT_TRUE(ResultStore(*db).beginUnit(old, &error)) << qPrintable(error);
        legacyId = old.id;
    }
    ResultWriter writer;
    writer.setSpoolFolder(dir.filePath(QStringLiteral("spool")));
    const ResultWriter::Opened opened = writer.openAndWait(path(), QStringLiteral("line 1"));
    ASSERT_TRUE(opened.ok) << qPrintable(opened.error);
    ASSERT_EQ(opened.interrupted.size(), 1);
    EXPECT_EQ(opened.interrupted.first().serial, QStringLiteral("SN-L1"));
    auto db = open();
    QString error;
    EXPECT_EQ(ResultStore(*db).statusOf(legacyId, &error), QStringLiteral("interrupted"));
    ResultWriter again;
    again.setSpoolFolder(dir.filePath(QStringLiteral("spool")));
    EXPECT_TRUE(again.openAndWait(path(), QStringLiteral("line 1")).interrupted.isEmpty());
}

TEST_F(ResultWriterTest, TwoLiveProcessesOfOneStationNeverInterruptEachOthersUnits)
{
    // The command line and the window on one PC, both with the host's name as station.
    ResultWriter window;
    window.setSpoolFolder(dir.filePath(QStringLiteral("spool")));
    ASSERT_TRUE(window.openAndWait(path(), QStringLiteral("line 1")).ok);
    QObject context;
    UnitRecord begun;
    bool answered = false;
    UnitRecord unit = test::eolSampleUnit(QStringLiteral("SN-W1"));
    unit.station = QStringLiteral("line 1");
    window.beginUnit(unit, &context, [&](const UnitRecord& r, const ResultWriter::Saved& saved) {
        EXPECT_TRUE(saved.error.isEmpty()) << qPrintable(saved.error);
        EXPECT_FALSE(saved.spooled);
        begun = r;
        answered = true;
    });
    ASSERT_TRUE(spinUntil([&] { return answered; }, 5000));

    ResultWriter commandLine;
    commandLine.setSpoolFolder(dir.filePath(QStringLiteral("spool")));
    const ResultWriter::Opened opened = commandLine.openAndWait(path(), QStringLiteral("line 1"));
    ASSERT_TRUE(opened.ok) << qPrintable(opened.error);
    EXPECT_TRUE(opened.interrupted.isEmpty());
    auto db = open();
    QString error;
    EXPECT_EQ(ResultStore(*db).statusOf(begun.id, &error), QStringLiteral("running"));
    EXPECT_EQ(StationLease(QStringLiteral("x"), QStringLiteral("y")).sweep(*db, nullptr, &error),
              true);
    EXPECT_EQ(ResultStore(*db).statusOf(begun.id, &error), QStringLiteral("running"));
}
