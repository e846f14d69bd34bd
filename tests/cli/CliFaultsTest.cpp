// What the command line says when it is given wrong options, files that are no backup files,
// outputs that are no regular files, the same setting twice, or a bus that does not answer.
#include "cli/ExitCode.h"
#include "tests/cli/CliTestSupport.h"
#include "tests/support/FifoReader.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <atomic>
#include <chrono>
#include <fcntl.h>
#include <future>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using namespace opentop;

namespace {

QStringList words(const char* line)
{
    return QString::fromLatin1(line).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

} // namespace

TEST(CliFaults, WrongConnectionOptionsAreUsageErrorsNamingTheRange)
{
    const struct
    {
        const char* option;
        const char* named;
    } cases[] = {
        {"--baud 123", "1200–115200"},   {"--timeout 0", "10–10000"},
        {"--retries 11", "0–10"},        {"--parity X", "N (none), E (even) or O (odd)"},
        {"--stop-bits 3", "use 1 or 2"}, {"--family xyz", "use one of dbu, dcpid"},
        {"--baud fast", "1200–115200"},  {"--timeout 20000", "10–10000"},
    };
    for (const auto& c : cases) {
        for (const char* command : {"get 1 spno2.speed", "backup 1 -o /tmp/never-written.json",
                                    "scan", "stop-all --yes"}) {
            const QString line = QStringLiteral("--port /dev/opentop-no-such-port %1 %2")
                                     .arg(QLatin1String(c.option), QLatin1String(command));
            const CliRun r = runCli(line.split(QLatin1Char(' ')));
            EXPECT_EQ(r.code, ExitUsage) << qPrintable(line + QLatin1Char('\n') + r.err);
            EXPECT_TRUE(r.err.contains(QString::fromUtf8(c.named))) << qPrintable(r.err);
            EXPECT_FALSE(r.err.contains(QStringLiteral("not checked"))) << qPrintable(r.err);
            EXPECT_FALSE(r.err.contains(QStringLiteral("no-such-port"))) << qPrintable(r.err);
        }
    }
    // The same on a simulated bus, where the serial settings were not even looked at.
    const CliRun sim = runCli(words("--sim dbu200@1 --variant 1=dbu200 --baud 123 get 1 "
                                    "spno2.speed"));
    EXPECT_EQ(sim.code, ExitUsage) << qPrintable(sim.out + sim.err);
    // No bus at all is a usage error too, said once.
    const CliRun none = runCli(words("get 1 spno2.speed"));
    EXPECT_EQ(none.code, ExitUsage) << qPrintable(none.err);
    EXPECT_EQ(none.err.count(QStringLiteral("no bus given")), 1) << qPrintable(none.err);
    EXPECT_FALSE(none.err.contains(QStringLiteral("not checked"))) << qPrintable(none.err);
}

TEST(CliFaults, UnknownVariantsAndMachineNumbersInVariantAreRefused)
{
    for (const char* variant :
         {"1=dbu999", "0=dbu200", "248=dbu200", "x=dbu200", "dbu999", "1=dbu200,2=dbu999"}) {
        const QString line = QStringLiteral("--sim dbu200@1 --variant %1 get 1 spno2.speed")
                                 .arg(QLatin1String(variant));
        const CliRun r = runCli(line.split(QLatin1Char(' ')));
        EXPECT_EQ(r.code, ExitUsage) << variant << qPrintable(r.out + r.err);
        EXPECT_TRUE(r.err.contains(QStringLiteral("--variant"))) << qPrintable(r.err);
    }
    const CliRun r = runCli(words("--sim dbu200@1 --variant 1=dbu999 get 1 spno2.speed"));
    EXPECT_TRUE(r.err.contains(QStringLiteral("use one of dbu200"))) << qPrintable(r.err);
    const CliRun ok = runCli(words("--sim dbu200@1 --variant 1=dbu200,dbu400 get 1 spno2.speed"));
    EXPECT_EQ(ok.code, ExitOk) << qPrintable(ok.err);
}

TEST(CliFaults, TheSameSettingTwiceIsRefusedWithNothingWritten)
{
    const CliRun r = runCli(words("--sim dbu200@1 --variant 1=dbu200 --trace set 1 "
                                  "spno2.speed=900 spno2.speed=1000"));
    EXPECT_EQ(r.code, ExitUsage) << qPrintable(r.out + r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("spno2.speed is given twice"))) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral(" 01 06 "))) << qPrintable(r.err); // no write
}

TEST(CliFaults, RestoreOfADeviceOrDirectorySaysWhatIsWrong)
{
    QTemporaryDir dir;
    CliRun r = runCli({QStringLiteral("--sim=dbu200@1"), QStringLiteral("restore"), dir.path()});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("is a directory"))) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("no such file"))) << qPrintable(r.err);
    r = runCli(
        {QStringLiteral("--sim=dbu200@1"), QStringLiteral("restore"), QStringLiteral("/dev/zero")});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("is not a regular file"))) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("no such file"))) << qPrintable(r.err);
    r = runCli({QStringLiteral("--sim=dbu200@1"), QStringLiteral("restore"),
                dir.filePath(QStringLiteral("missing.json"))});
    EXPECT_TRUE(r.err.contains(QStringLiteral("no such file"))) << qPrintable(r.err);
}

TEST(CliFaults, AHugeBackupFileIsRefusedNamingTheCap)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("huge.json"));
    QFile huge(path);
    ASSERT_TRUE(huge.open(QIODevice::WriteOnly));
    ASSERT_TRUE(huge.resize(100LL * 1024 * 1024)); // sparse
    huge.close();
    const CliRun r = runCli({QStringLiteral("--sim=dbu200@1"), QStringLiteral("restore"), path});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("larger than 16 MB"))) << qPrintable(r.err);
}

TEST(CliFaults, BackupToAFifoWritesThroughItAndToADirectoryIsRefusedFirst)
{
    QTemporaryDir dir;
    const QString fifo = dir.filePath(QStringLiteral("pipe"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    std::atomic<bool> writerDone{false};
    auto read = opentop::test::readFifo(fifo, &writerDone);
    CliRun r = runCli({QStringLiteral("--sim=dbu200@1"), QStringLiteral("--variant=1=dbu200"),
                       QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"), fifo});
    writerDone = true;
    const QByteArray data = read.get();
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    struct stat st
    {
    };
    ASSERT_EQ(::stat(QFile::encodeName(fifo).constData(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced by a regular file";
    EXPECT_TRUE(data.contains("opentop-backup"));

    r = runCli({QStringLiteral("--sim=dbu200@1"), QStringLiteral("--variant=1=dbu200"),
                QStringLiteral("--trace"), QStringLiteral("backup"), QStringLiteral("1"),
                QStringLiteral("-o"), dir.path()});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("it is a directory"))) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral(" 01 03 "))) << qPrintable(r.err); // nothing read
}

TEST(CliFaults, StopAllOnADeadBusIsNotConfirmed)
{
    const CliRun r = runCli(words("--sim dbu200@1 --timeout 50 --retries 0 --json stop-all --yes "
                                  "--ids 5"));
    EXPECT_EQ(r.code, ExitCommunication) << qPrintable(r.out + r.err);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_FALSE(o.value(QStringLiteral("confirmed")).toBool(true)) << qPrintable(r.out);
    EXPECT_TRUE(o.value(QStringLiteral("checked")).toBool()) << qPrintable(r.out);
}
