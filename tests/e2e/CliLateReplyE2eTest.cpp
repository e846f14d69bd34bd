// opentop-cli over a pty against opentop-sim whose drives answer late now and then (issue 11,
// item 1): a reply that comes after the timeout must never pass for the answer to the retry or
// to the next request. Every value the program reads (backup file, compare, restore's check) is
// compared with what the simulated drive really holds.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

using namespace opentop::test;

namespace {

class CliLateReplyE2e : public ::testing::Test
{
protected:
    void SetUp() override
    {
        // 10 % of the replies come 300 ms after the request: 100 ms after the default 200 ms
        // timeout, long after a frame time.
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                               QStringLiteral("--wire-timing"), QStringLiteral("--baud"),
                               QStringLiteral("19200"), QStringLiteral("--faults"),
                               QStringLiteral("late=0.1,late_ms=300"), QStringLiteral("--seed"),
                               QStringLiteral("7")},
                              &error))
            << error.toStdString();
        ASSERT_TRUE(dir.isValid());
        file = dir.filePath(QStringLiteral("late.json"));
    }

    CliResult run(const QStringList& command)
    {
        QProcess cli;
        cli.start(cliProgram(),
                  QStringList{QStringLiteral("--port"), sim.pty, QStringLiteral("--variant"),
                              QStringLiteral("1=dbu200"), QStringLiteral("--bus-drives=1")} +
                      command);
        EXPECT_TRUE(cli.waitForStarted(5000));
        return finishCli(cli, 15000);
    }

    // Every register of every setting in the backup file, compared with the simulated drive.
    int registersDifferingFromTheDrive()
    {
        QFile f(file);
        EXPECT_TRUE(f.open(QIODevice::ReadOnly));
        const QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
        int differing = 0;
        int checked = 0;
        for (const QJsonValue& device : root.value(QStringLiteral("devices")).toArray()) {
            const int slave = device.toObject().value(QStringLiteral("slave")).toInt();
            for (const QJsonValue& p :
                 device.toObject().value(QStringLiteral("parameters")).toArray()) {
                const QJsonObject parameter = p.toObject();
                const int address =
                    parameter.value(QStringLiteral("address")).toString().toInt(nullptr, 16);
                const QJsonArray registers = parameter.value(QStringLiteral("registers")).toArray();
                for (int i = 0; i < registers.size(); ++i) {
                    ++checked;
                    const int held = sim.get(slave, address + i);
                    if (held != registers[i].toInt()) {
                        ++differing;
                        ADD_FAILURE()
                            << parameter.value(QStringLiteral("name")).toString().toStdString()
                            << " register " << i << ": file " << registers[i].toInt() << ", drive "
                            << held;
                    }
                }
            }
        }
        EXPECT_GT(checked, 60);
        return differing;
    }

    SimProcess sim;
    QTemporaryDir dir;
    QString file;
};

} // namespace

TEST_F(CliLateReplyE2e, BackupCompareAndRestoreNeverTakeALateReplyForAnotherAnswer)
{
    CliResult r = run({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_EQ(registersDifferingFromTheDrive(), 0);

    // A late reply used to answer the next read of the same length: compare then listed
    // differences that do not exist.
    for (int i = 0; i < 3; ++i) {
        r = run({QStringLiteral("compare"), file, QStringLiteral("1")});
        EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
        EXPECT_TRUE(r.out.contains(QStringLiteral("no differences"))) << r.out.toStdString();
    }

    // Two settings changed on the drive: the restore must see both as different, write them
    // and verify them with the drive's real values.
    sim.command(QStringLiteral("set 1 0xCA03 1500"));
    const int countdown = sim.get(1, 0x1017); // va.countdown
    sim.command(QStringLiteral("set 1 0x1017 %1").arg(countdown == 0 ? 1 : 0));
    r = run({QStringLiteral("restore"), file, QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("2 written and verified"))) << r.out.toStdString();
    EXPECT_EQ(sim.get(1, 0xCA03), 1000);
    EXPECT_EQ(sim.get(1, 0x1017), countdown);
    EXPECT_EQ(registersDifferingFromTheDrive(), 0);

    r = run({QStringLiteral("compare"), file, QStringLiteral("1")});
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("no differences"))) << r.out.toStdString();
}
