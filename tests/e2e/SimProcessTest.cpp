// opentop-sim as a program: console, arguments, shutdown, and third-party cross-checks with
// mbpoll.
#include "tests/e2e/SimProcess.h"

#include "transport/ConnectionSettings.h"
#include "transport/ModbusClient.h"
#include "transport/ModbusRequest.h"
#include "transport/RtuBackend.h"

#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>

using namespace opentop;
using namespace opentop::test;

namespace {

// Runs mbpoll once and returns the value it printed for the register, or nothing.
std::optional<int> mbpoll(const QStringList& arguments, QString* output)
{
    QProcess p;
    p.start(QStringLiteral("mbpoll"), arguments);
    if (!p.waitForFinished(10000))
        return std::nullopt;
    *output = QString::fromLocal8Bit(p.readAllStandardOutput() + p.readAllStandardError());
    static const QRegularExpression value(QStringLiteral("^\\[\\d+\\]:\\s+(-?\\d+)"),
                                          QRegularExpression::MultilineOption);
    const QRegularExpressionMatch m = value.match(*output);
    if (!m.hasMatch())
        return std::nullopt;
    return m.captured(1).toInt();
}

bool haveMbpoll()
{
    return !QStandardPaths::findExecutable(QStringLiteral("mbpoll")).isEmpty();
}

void write(const QString& pty, const QVector<ModbusRequest>& requests)
{
    ConnectionSettings s;
    s.port = pty;
    s.retries = 0;
    ModbusClient client(std::make_unique<RtuBackend>(s), s);
    ASSERT_TRUE(client.openBlocking().isEmpty());
    for (const ModbusRequest& r : requests)
        ASSERT_TRUE(client.execute(r).ok()) << r.describe().toStdString();
}

} // namespace

TEST(SimProcess, MbpollReadsTheDbuCurrentSpeed)
{
    if (!haveMbpoll())
        GTEST_SKIP() << "mbpoll is not installed (apt-get install mbpoll) - cross-check skipped";
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dcpid@7")}));
    write(sim.pty,
          {ModbusRequest::writeSingle(1, 0x100D, 2), ModbusRequest::writeSingle(1, 0x200F, 2),
           ModbusRequest::writeSingle(1, 0x2003, 1)});
    QThread::msleep(500); // SPno3: 1350 r/min after a 0.5 s ramp for 3000 r/min
    QString out;
    const std::optional<int> speed = mbpoll(
        {QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-a"), QStringLiteral("1"),
         QStringLiteral("-b"), QStringLiteral("19200"), QStringLiteral("-P"),
         QStringLiteral("none"), QStringLiteral("-t"), QStringLiteral("3"), QStringLiteral("-0"),
         QStringLiteral("-r"), QStringLiteral("0x0109"), QStringLiteral("-1"), sim.pty},
        &out);
    ASSERT_TRUE(speed) << out.toStdString();
    EXPECT_EQ(*speed, 1350);
    EXPECT_EQ(*speed, sim.get(1, 0x0109, 4));
}

TEST(SimProcess, MbpollReadsTheDcPwm)
{
    if (!haveMbpoll())
        GTEST_SKIP() << "mbpoll is not installed (apt-get install mbpoll) - cross-check skipped";
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dcpid@7")}));
    write(sim.pty, {ModbusRequest::writeSingle(7, 0x0040, 420)}); // 42.0 % duty
    QThread::msleep(400);
    QString out;
    const std::optional<int> pwm = mbpoll(
        {QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-a"), QStringLiteral("7"),
         QStringLiteral("-b"), QStringLiteral("19200"), QStringLiteral("-P"),
         QStringLiteral("none"), QStringLiteral("-t"), QStringLiteral("4"), QStringLiteral("-0"),
         QStringLiteral("-r"), QStringLiteral("0x0010"), QStringLiteral("-1"), sim.pty},
        &out);
    ASSERT_TRUE(pwm) << out.toStdString();
    EXPECT_EQ(*pwm, 420);
    EXPECT_EQ(*pwm, sim.get(7, 0x0010));
}

TEST(SimProcess, SigtermExitsCleanlyAndRemovesTheSymlink)
{
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("ttySIM0"));
    SimProcess sim;
    ASSERT_TRUE(sim.start(
        {QStringLiteral("--devices"), QStringLiteral("dbu200@1"), QStringLiteral("--pty"), link}));
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), sim.pty);
    // The link works like the pty itself.
    write(link, {ModbusRequest::writeSingle(1, 0xCA05, 2000)});
    EXPECT_EQ(sim.get(1, 0xCA05), 2000);
    EXPECT_EQ(sim.terminate(), 0);
    EXPECT_FALSE(QFileInfo(link).isSymLink());
}

TEST(SimProcess, QuitCommandAndConsole)
{
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1")}));
    EXPECT_TRUE(sim.command(QStringLiteral("vr 1 750")).contains(QStringLiteral("750")));
    EXPECT_EQ(sim.get(1, 0xCA01), 750);
    EXPECT_TRUE(sim.command(QStringLiteral("alarm 1 3")).contains(QStringLiteral("raised")));
    EXPECT_EQ(sim.get(1, 0x1C01, 4), 3);
    EXPECT_TRUE(sim.command(QStringLiteral("vr 1 99999")).startsWith(QLatin1String("error:")));
    EXPECT_TRUE(sim.command(QStringLiteral("list")).startsWith(QLatin1String("1 dbu200")));
    sim.process().write("quit\n");
    ASSERT_TRUE(sim.process().waitForFinished(5000));
    EXPECT_EQ(sim.process().exitCode(), 0);
}

TEST(SimProcess, BadArgumentsExitWithCode2)
{
    struct Case
    {
        QStringList arguments;
        const char* mention;
    };
    const Case cases[] = {
        {{QStringLiteral("--devices"), QStringLiteral("dbu200@1"), QStringLiteral("--parity"),
          QStringLiteral("X")},
         "N, E or O"},
        {{QStringLiteral("--devices"), QStringLiteral("foo@1")}, "dbu200"},
        {{QStringLiteral("--pty")}, "--devices"},
        {{QStringLiteral("--devices"), QStringLiteral("dbu200@1"), QStringLiteral("--faults"),
          QStringLiteral("drop=3")},
         "0..1"},
    };
    for (const Case& c : cases) {
        QProcess p;
        p.start(SimProcess::program(), c.arguments);
        ASSERT_TRUE(p.waitForFinished(5000));
        EXPECT_EQ(p.exitCode(), 2) << c.arguments.join(QLatin1Char(' ')).toStdString();
        const QString err = QString::fromLocal8Bit(p.readAllStandardError());
        EXPECT_TRUE(err.contains(QLatin1String(c.mention))) << err.toStdString();
    }
    QProcess help;
    help.start(SimProcess::program(), {QStringLiteral("--help")});
    ASSERT_TRUE(help.waitForFinished(5000));
    EXPECT_EQ(help.exitCode(), 0);
    EXPECT_TRUE(help.readAllStandardOutput().contains("--wire-timing"));
}
