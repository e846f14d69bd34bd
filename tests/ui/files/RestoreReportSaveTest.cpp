// Saving the restore report goes through OutputFile: a FIFO or device is written through (never
// replaced by a regular file), a missing folder or a directory is an error, not success.
#include "tests/support/FifoReader.h"
#include "ui/files/RestoreReport.h"

#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

QVector<RestorePlan> onePlan()
{
    RestorePlan plan;
    plan.title = QStringLiteral("drive 1 (DBU200-D)");
    plan.deviceRead = true;
    return {plan};
}

} // namespace

TEST(RestoreReportSaveTest, AFifoIsWrittenThroughAndStaysAFifo)
{
    QTemporaryDir dir;
    const QVector<RestorePlan> plans = onePlan();
    bool ok = false;
    QString error;
    bool stillFifo = false;
    const QByteArray got = test::saveThroughFifo(
        dir.path(),
        [&](const QString& path) {
            ok = RestoreReport::save(path, QStringLiteral("drives.json"), plans, true, &error);
        },
        &stillFifo);
    EXPECT_TRUE(ok) << qPrintable(error);
    EXPECT_TRUE(stillFifo) << "the FIFO was replaced by a regular file";
    EXPECT_EQ(QString::fromUtf8(got),
              RestoreReport::text(QStringLiteral("drives.json"), plans, true));
}

TEST(RestoreReportSaveTest, AMissingFolderOrADirectoryIsAnError)
{
    QTemporaryDir dir;
    QString error;
    const QString missing = dir.filePath(QStringLiteral("no-such-folder/report.txt"));
    EXPECT_FALSE(RestoreReport::save(missing, QStringLiteral("d.json"), onePlan(), true, &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("cannot write ") + missing)) << qPrintable(error);
    EXPECT_FALSE(QFile::exists(missing));
    EXPECT_FALSE(
        RestoreReport::save(dir.path(), QStringLiteral("d.json"), onePlan(), true, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("it is a directory"))) << qPrintable(error);
}
