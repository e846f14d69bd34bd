// Gives a test process its own settings, data and cache folders (and late-reply journal). ctest
// runs two test processes at once, and QSettings is one file per user: a test clearing the settings
// in its set-up erased what a test running beside it had just remembered (CI failed so, once).
#pragma once
#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace opentop::test {

class PrivateUserDirs
{
public:
    // Before the application object exists, so Qt reads the folders from the environment;
    // programs the test starts inherit them.
    PrivateUserDirs()
    {
        if (!m_dir.isValid())
            return;
        for (const char* name : {"config", "data", "cache"}) {
            const QString path = m_dir.filePath(QString::fromLatin1(name));
            QDir().mkpath(path);
            const QByteArray var = QByteArray("XDG_") + QByteArray(name).toUpper() + "_HOME";
            qputenv(var.constData(), QFile::encodeName(path));
        }
        // The late-reply journal is per device, and ptys are numbered again as tests end:
        // one test process must not inherit another's (LateReplyJournal).
        const QString late = m_dir.filePath(QStringLiteral("late"));
        qputenv("OPENTOP_LATE_JOURNAL_DIR", QFile::encodeName(late));
    }

    // After InitGoogleTest: each test starts with no late-reply journal, as on a machine
    // where nothing used the port before (ptys are numbered again as tests end, so a test
    // would otherwise inherit what the one before left for the same /dev/pts number).
    static void startEachTestWithoutJournal()
    {
        struct Listener : ::testing::EmptyTestEventListener
        {
            void OnTestStart(const ::testing::TestInfo&) override
            {
                QDir(qEnvironmentVariable("OPENTOP_LATE_JOURNAL_DIR")).removeRecursively();
            }
        };
        ::testing::UnitTest::GetInstance()->listeners().Append(new Listener);
    }

private:
    QTemporaryDir m_dir;
};

} // namespace opentop::test
