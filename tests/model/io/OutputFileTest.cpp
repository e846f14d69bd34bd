// Writing a file the safe way for what its path names: a regular file is replaced atomically,
// a device or FIFO is written through (never replaced by a regular file) with every write
// error reported, a directory is refused; and a backup file too large to be one is refused
// without being read.
#include "model/io/OutputFile.h"
#include "model/files/BackupFile.h"
#include "model/profile/ProfileRegistry.h"
#include "tests/support/FifoReader.h"
#include "tests/support/FileSizeLimit.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
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

bool isFifo(const QString& path)
{
    struct stat st
    {
    };
    return ::stat(QFile::encodeName(path).constData(), &st) == 0 && S_ISFIFO(st.st_mode);
}

bool isCharDevice(const QString& path)
{
    struct stat st
    {
    };
    return ::stat(QFile::encodeName(path).constData(), &st) == 0 && S_ISCHR(st.st_mode);
}

} // namespace

TEST(OutputFile, AFifoIsWrittenThroughAndStaysAFifo)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("pipe"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
    std::atomic<bool> done{false};
    auto read = opentop::test::readFifo(path, &done);
    QString error;
    EXPECT_TRUE(OutputFile::write(path, QByteArray("hello\n"), &error)) << qPrintable(error);
    done = true;
    EXPECT_EQ(read.get(), QByteArray("hello\n"));
    EXPECT_TRUE(isFifo(path));
}

TEST(OutputFile, ABackupSavedToAFifoLeavesTheFifoInPlace)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("pipe"));
    ASSERT_EQ(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
    std::atomic<bool> done{false};
    auto read = opentop::test::readFifo(path, &done);
    BackupFile file;
    file.tool = BackupFile::toolName();
    file.created = QDateTime::currentDateTimeUtc();
    QString error;
    const bool saved = file.save(path, ProfileRegistry::builtIn(), &error);
    done = true;
    const QByteArray data = read.get();
    EXPECT_TRUE(saved) << qPrintable(error);
    EXPECT_TRUE(isFifo(path)) << "the FIFO was replaced by a regular file";
    EXPECT_TRUE(data.contains("opentop-backup")) << data.constData();
}

TEST(OutputFile, AFullDeviceReportsTheWriteErrorAndIsNotReplaced)
{
    const QString full = QStringLiteral("/dev/full");
    if (!isCharDevice(full))
        GTEST_SKIP() << "no /dev/full here";
    QString error;
    EXPECT_FALSE(OutputFile::write(full, QByteArray(4096, 'x'), &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("cannot write /dev/full: "))) << qPrintable(error);
    EXPECT_TRUE(error.contains(QStringLiteral("No space left on device"))) << qPrintable(error);
    EXPECT_TRUE(isCharDevice(full));
}

TEST(OutputFile, ADirectoryIsRefusedAndARegularFileReplaced)
{
    QTemporaryDir dir;
    QString error;
    EXPECT_FALSE(OutputFile::write(dir.path(), QByteArray("x"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("directory"))) << qPrintable(error);
    EXPECT_TRUE(OutputFile::problem(dir.path()).contains(QStringLiteral("directory")));
    EXPECT_TRUE(OutputFile::problem(dir.filePath(QStringLiteral("no/such/x.json")))
                    .contains(QStringLiteral("does not exist")));

    const QString path = dir.filePath(QStringLiteral("a.json"));
    EXPECT_TRUE(OutputFile::problem(path).isEmpty());
    ASSERT_TRUE(OutputFile::write(path, QByteArray("first"), &error)) << qPrintable(error);
    ASSERT_TRUE(OutputFile::write(path, QByteArray("second"), &error)) << qPrintable(error);
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_EQ(f.readAll(), QByteArray("second"));
    // A link to a regular file: the file it names is replaced, the link kept.
    const QString link = dir.filePath(QStringLiteral("link.json"));
    ASSERT_TRUE(QFile::link(path, link));
    ASSERT_TRUE(OutputFile::write(link, QByteArray("third"), &error)) << qPrintable(error);
    EXPECT_TRUE(QFileInfo(link).isSymLink());
    QFile g(path);
    ASSERT_TRUE(g.open(QIODevice::ReadOnly));
    EXPECT_EQ(g.readAll(), QByteArray("third"));
}

TEST(BackupFileSize, AFileLargerThanTheCapIsRefusedNamingTheCap)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("huge.json"));
    QFile huge(path);
    ASSERT_TRUE(huge.open(QIODevice::WriteOnly));
    ASSERT_TRUE(huge.resize(100LL * 1024 * 1024)); // sparse: no disk used
    huge.close();
    QString error;
    EXPECT_FALSE(BackupFile::load(path, ProfileRegistry::builtIn(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("larger than 16 MB"))) << qPrintable(error);
}

// A disk that fills: a small file (Qt 6.4 missed the error of a buffered write under 16 KB
// and renamed an empty file over the old one) is refused with the reason, the old file stays
// whole, and no temporary file is left beside it.
TEST(OutputFile, AWriteTheFileSystemRefusesKeepsTheOldFileAndSaysWhy)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("site.json"));
    const QByteArray old = QByteArrayLiteral("{\"old\": true}\n");
    QString error;
    ASSERT_TRUE(OutputFile::write(path, old, &error)) << qPrintable(error);
    for (const int size : {100, 8 * 1024, 40 * 1024}) {
        {
            test::FileSizeLimit limit(64);
            ASSERT_TRUE(limit.ok());
            error.clear();
            EXPECT_FALSE(OutputFile::write(path, QByteArray(size, 'x'), &error)) << size;
        }
        EXPECT_TRUE(error.startsWith(QStringLiteral("cannot write %1: ").arg(path)))
            << qPrintable(error);
        QFile kept(path);
        ASSERT_TRUE(kept.open(QIODevice::ReadOnly));
        EXPECT_EQ(kept.readAll(), old) << "after a " << size << "-byte write";
        EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files),
                  QStringList{QStringLiteral("site.json")});
    }
    EXPECT_TRUE(OutputFile::write(path, QByteArray(8 * 1024, 'y'), &error)) << qPrintable(error);
    EXPECT_EQ(QFileInfo(path).size(), 8 * 1024);
}
