// monitor, alarms, run and stop-all in process against --sim buses, with wrong values and
// missing confirmations.
#include "cli/CliApp.h"
#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "connection/ConnectionOptions.h"
#include "sim/SimBus.h"
#include "tests/cli/CliTestSupport.h"
#include "transport/ModbusClient.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QThread>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

QStringList words(const char* line)
{
    return QString::fromUtf8(line).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

// Like runCli, but `setup` prepares the simulated drives (alarms, priority, a started motor)
// through the bus before the command runs, as a previous command or the console would have.
CliRun runPrepared(const QStringList& args, const std::function<void(CliContext&)>& setup)
{
    CliRun r;
    QTextStream out(&r.out);
    QTextStream err(&r.err);
    CliApp app;
    QCommandLineParser parser;
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    QSet<QString> added;
    auto add = [&](const QCommandLineOption& o) {
        if (added.contains(o.names().first()))
            return;
        added.insert(o.names().first());
        parser.addOption(o);
    };
    add({QStringLiteral("json"), QString()});
    add({QStringLiteral("trace"), QString()});
    add({QStringLiteral("variant"), QString(), QStringLiteral("V")});
    ConnectionOptions::addTo(parser);
    for (const auto& c : app.commands())
        for (const QCommandLineOption& o : c->options())
            add(o);
    EXPECT_TRUE(parser.parse(QStringList{QStringLiteral("opentop-cli")} + args))
        << qPrintable(parser.errorText());
    CliContext context(parser, out, err);
    EXPECT_TRUE(context.connectBus());
    setup(context);
    const QStringList positional = parser.positionalArguments();
    for (const auto& c : app.commands()) {
        if (c->name() == positional.value(0))
            r.code = c->run(context, positional.mid(1));
    }
    out.flush();
    err.flush();
    return r;
}

void control(CliContext& context, int slave, const char* line)
{
    const SimControlResult r = context.simBus()->control(slave, words(line));
    EXPECT_TRUE(r.ok) << qPrintable(r.text);
}

// Starts the DBU at `slave` over the bus, in communication priority.
void startDrive(CliContext& context, int slave)
{
    control(context, slave, "set 0x100D 2");
    const ModbusResult r =
        context.client()->execute(ModbusRequest::writeSingle(quint8(slave), 0x2003, 1));
    EXPECT_TRUE(r.ok()) << qPrintable(r.errorText());
    // Until it runs at the Ext-VR's 500 r/min.
    QElapsedTimer timer;
    timer.start();
    while (context.client()
                   ->execute(ModbusRequest::readInput(quint8(slave), 0x0109, 1))
                   .registers.value(0) != 500 &&
           timer.elapsed() < 5000)
        QThread::msleep(10);
}

const QString kDbu = QStringLiteral("--sim=dbu200@1");

} // namespace

TEST(DriveCommands, HelpListsTheDriveCommands)
{
    const CliRun r = runCli({QStringLiteral("--help")});
    for (const char* c : {"monitor ID...", "alarms ID", "run ID", "stop-all --yes"})
        EXPECT_TRUE(r.out.contains(QLatin1String(c))) << c;
    const CliRun help = runCli(words("help monitor"));
    EXPECT_EQ(help.code, ExitOk);
    EXPECT_TRUE(help.out.contains(QStringLiteral("--interval MS"))) << qPrintable(help.out);
}

TEST(DriveCommands, MonitorPrintsAlignedLinesWithUnits)
{
    const CliRun r = runCli(words("--sim dbu200@1 monitor 1 --count 3 --interval 50"));
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 4) << qPrintable(r.out);
    for (const char* h : {"Time", "ID", "Current speed", "Speed shown", "Target speed", "Load rate",
                          "Running status", "Running direction", "X0", "X3", "Y1", "Active alarm"})
        EXPECT_TRUE(lines[0].contains(QLatin1String(h))) << h << " in " << qPrintable(lines[0]);
    const int speedColumn = int(lines[0].indexOf(QStringLiteral("Current speed")));
    for (int i = 1; i < 4; ++i) {
        EXPECT_TRUE(QRegularExpression(QStringLiteral("^\\d\\d:\\d\\d:\\d\\d\\.\\d{3}  +1  "))
                        .match(lines[i])
                        .hasMatch())
            << qPrintable(lines[i]);
        EXPECT_TRUE(lines[i].contains(QStringLiteral("0 r/min")));
        EXPECT_TRUE(lines[i].contains(QStringLiteral("0.000 r/min")));
        EXPECT_TRUE(lines[i].contains(QStringLiteral("0 %")));
        EXPECT_TRUE(lines[i].contains(QStringLiteral("Stopped")));
        EXPECT_TRUE(lines[i].endsWith(QStringLiteral("none")));
        // Right-aligned under its header: the value ends where the header does.
        EXPECT_EQ(lines[i].mid(speedColumn, 13).trimmed(), QStringLiteral("0 r/min"));
    }
}

TEST(DriveCommands, MonitorJsonLinesAndTwoFamilies)
{
    const CliRun r =
        runCli(words("--sim dbu200@1,dcpid@7 --json monitor 1,7 --count 2 --interval 50"));
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 4) << qPrintable(r.out);
    int dbu = 0;
    int dc = 0;
    for (const QString& line : lines) {
        QJsonParseError e;
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8(), &e).object();
        ASSERT_EQ(e.error, QJsonParseError::NoError) << qPrintable(line);
        EXPECT_TRUE(o.value(QStringLiteral("timestamp")).toString().contains(QLatin1Char('.')));
        const QJsonObject values = o.value(QStringLiteral("values")).toObject();
        if (o.value(QStringLiteral("slave")).toInt() == 1) {
            ++dbu;
            EXPECT_EQ(values.value(QStringLiteral("status.current_speed"))
                          .toObject()
                          .value(QStringLiteral("unit"))
                          .toString(),
                      QStringLiteral("r/min"));
            EXPECT_EQ(o.value(QStringLiteral("display"))
                          .toObject()
                          .value(QStringLiteral("currentSpeed"))
                          .toObject()
                          .value(QStringLiteral("text"))
                          .toString(),
                      QStringLiteral("0.000"));
            EXPECT_FALSE(o.value(QStringLiteral("alarmActive")).toBool(true));
        } else {
            ++dc;
            EXPECT_TRUE(values.contains(QStringLiteral("status.ai_diff")));
            EXPECT_EQ(values.value(QStringLiteral("status.current"))
                          .toObject()
                          .value(QStringLiteral("unit"))
                          .toString(),
                      QStringLiteral("A"));
        }
        EXPECT_FALSE(o.value(QStringLiteral("running")).toBool(true));
    }
    EXPECT_EQ(dbu, 2);
    EXPECT_EQ(dc, 2);
}

TEST(DriveCommands, MonitorWritesCsvWithUnitsInTheHeader)
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("log.csv"));
    const CliRun r =
        runCli({kDbu, QStringLiteral("monitor"), QStringLiteral("1"), QStringLiteral("--count=2"),
                QStringLiteral("--interval=50"), QStringLiteral("--csv"), file});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    QFile f(file);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QStringList lines =
        QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 3);
    EXPECT_TRUE(lines[0].startsWith(QStringLiteral("timestamp,slave,family,status.current_speed "
                                                   "[r/min],status.current_speed.display [r/min]")))
        << qPrintable(lines[0]);
    EXPECT_TRUE(lines[0].contains(QStringLiteral("status.load [%]")));
    EXPECT_TRUE(lines[0].endsWith(QStringLiteral(",alarm,note"))); // note: a lost link's rows
    const QRegularExpression row(
        QStringLiteral("^\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d\\.\\d{3}[^,]*,1,dbu,0,0.000,"));
    for (int i = 1; i < 3; ++i)
        EXPECT_TRUE(row.match(lines[i]).hasMatch()) << qPrintable(lines[i]);
    EXPECT_EQ(lines[1].count(QLatin1Char(',')), lines[0].count(QLatin1Char(',')));
}

TEST(DriveCommands, MonitorRefusesWrongValues)
{
    for (const char* line :
         {"--sim dbu200@1 monitor 1 --interval 10", "--sim dbu200@1 monitor 1 --interval 70000",
          "--sim dbu200@1 monitor 1 --interval x", "--sim dbu200@1 monitor 1 --count 0",
          "--sim dbu200@1 monitor", "--sim dbu200@1 monitor 300"}) {
        const CliRun r = runCli(words(line));
        EXPECT_EQ(r.code, ExitUsage) << line << ": " << qPrintable(r.err);
        EXPECT_TRUE(r.err.startsWith(QStringLiteral("error:"))) << qPrintable(r.err);
    }
    const CliRun file = runCli(words("--sim dbu200@1 monitor 1 --csv /nonexistent/dir/x.csv"));
    EXPECT_EQ(file.code, ExitInvalid) << qPrintable(file.err);
    const CliRun absent = runCli(words("--sim dbu200@1 --timeout 50 monitor 5 --count 1"));
    EXPECT_EQ(absent.code, ExitCommunication);
    EXPECT_TRUE(absent.err.contains(QStringLiteral("machine number 5"))) << qPrintable(absent.err);
}

TEST(DriveCommands, AlarmsShowHistoriesWithCauseAndRemedy)
{
    const CliRun empty = runCli(words("--sim dbu200@1 alarms 1"));
    EXPECT_EQ(empty.code, ExitOk) << qPrintable(empty.err);
    EXPECT_TRUE(empty.out.contains(QStringLiteral("No alarm is active.")));
    EXPECT_TRUE(empty.out.contains(QStringLiteral("Alarm codes: no records.")));
    EXPECT_TRUE(empty.out.contains(QStringLiteral("(status.comm_error): none (0)")));

    const CliRun r = runPrepared(words("--sim dbu200@1 alarms 1"), [](CliContext& c) {
        control(c, 1, "alarm 0x0B");
        control(c, 1, "power-cycle");
        control(c, 1, "alarm 7");
        control(c, 1, "warning 0x17");
    });
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Alarm active: AL007 Overload.")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Alarm codes: 2 of 15 records, newest first")));
    EXPECT_TRUE(QRegularExpression(QStringLiteral("\\n1  07h   AL007  Overload +Alarm-Reset\\n"))
                    .match(r.out)
                    .hasMatch())
        << qPrintable(r.out);
    EXPECT_TRUE(
        QRegularExpression(QStringLiteral("\\n2  0Bh   AL00B  Hall signal error +power cycle"))
            .match(r.out)
            .hasMatch());
    EXPECT_TRUE(r.out.contains(QStringLiteral("WR017  Low voltage")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("  Remedy: ")));
    EXPECT_LT(r.out.indexOf(QStringLiteral("\nAL007 Overload\n")),
              r.out.indexOf(QStringLiteral("\nAL00B Hall signal error\n")));

    const CliRun json = runPrepared(words("--sim dbu200@1 --json alarms 1"),
                                    [](CliContext& c) { control(c, 1, "alarm 7"); });
    EXPECT_EQ(json.code, ExitOk);
    const QJsonObject o = QJsonDocument::fromJson(json.out.toUtf8()).object();
    const QJsonObject first = o.value(QStringLiteral("alarm"))
                                  .toObject()
                                  .value(QStringLiteral("records"))
                                  .toArray()
                                  .at(0)
                                  .toObject();
    EXPECT_EQ(first.value(QStringLiteral("panel")).toString(), QStringLiteral("AL007"));
    EXPECT_TRUE(o.value(QStringLiteral("alarmActive")).toBool());
    EXPECT_EQ(o.value(QStringLiteral("commError")).toObject().value(QStringLiteral("code")).toInt(),
              0);
}

TEST(DriveCommands, AlarmChangesNeedYes)
{
    CliRun r = runCli(words("--sim dbu200@1 alarms 1 --reset"));
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("cmd.alarm_reset = Reset (0) (0x1200, function 06)")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--yes")));
    r = runCli(words("--sim dbu200@1 alarms 1 --clear-records"));
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("cmd.erase_alarms = Erase (1)")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("cmd.erase_warnings = Erase (1)")));
    for (const char* line : {"--sim dbu200@1 alarms", "--sim dbu200@1 alarms 1 2",
                             "--sim dbu200@1,dcpid@7 alarms 7", "--sim dbu200@1 alarms 1,2"})
        EXPECT_EQ(runCli(words(line)).code, ExitUsage) << line;
}

TEST(DriveCommands, AlarmResetAndClearRecords)
{
    CliRun r = runPrepared(words("--sim dbu200@1 alarms 1 --reset --yes"),
                           [](CliContext& c) { control(c, 1, "alarm 7"); });
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Alarm reset: AL007 Overload is cleared.")))
        << qPrintable(r.out);

    r = runPrepared(words("--sim dbu200@1 alarms 1 --reset --yes"),
                    [](CliContext& c) { control(c, 1, "alarm 1"); });
    EXPECT_EQ(r.code, ExitMismatch) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("AL001 Overvoltage is still active: only a power "
                                              "cycle clears it.")))
        << qPrintable(r.out);

    r = runPrepared(words("--sim dbu200@1 alarms 1 --reset --yes"), [](CliContext& c) {
        control(c, 1, "set 0x1005 0");
        control(c, 1, "alarm 7");
    });
    EXPECT_EQ(r.code, ExitMismatch) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("set to clear alarms by a power restart only "
                                              "(core.alarm_erase = Restart power)")))
        << qPrintable(r.out);

    r = runPrepared(words("--sim dbu200@1 alarms 1 --clear-records --yes"), [](CliContext& c) {
        control(c, 1, "alarm 7");
        control(c, 1, "warning 5");
    });
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(
        QStringLiteral("Erased: Alarm codes, Warning codes (2 records); read back empty.")))
        << qPrintable(r.out);
}

TEST(DriveCommands, RunNeedsYesAndSaysWhatWouldBeSent)
{
    const CliRun r = runCli(words("--sim dbu200@1 run 1 start"));
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral(
        "Would send to machine number 1: run.start = START (1) (0x2003, function 06)")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("add --yes")));
    const CliRun select = runCli(words("--sim dbu200@1 run 1 select 8"));
    EXPECT_TRUE(select.err.contains(QStringLiteral("run.select = SPno8 (7)")))
        << qPrintable(select.err);
}

TEST(DriveCommands, RunRefusesADriveInIoPriority)
{
    const CliRun r = runCli(words("--sim dbu200@1 run 1 start --yes"));
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("is in \"I/O priority\" (core.control_priority); "
                                              "nothing was sent")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("opentop-cli set 1 core.control_priority=2")));
}

TEST(DriveCommands, RunStartsAndShowsTheState)
{
    CliRun r = runPrepared(words("--sim dbu200@1 run 1 start --yes"),
                           [](CliContext& c) { control(c, 1, "set 0x100D 2"); });
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Sent to machine number 1: run.start = START (1)")));
    EXPECT_TRUE(
        QRegularExpression(QStringLiteral("Running status +Running\\n")).match(r.out).hasMatch())
        << qPrintable(r.out);
    EXPECT_TRUE(
        QRegularExpression(QStringLiteral("Target speed +500 r/min")).match(r.out).hasMatch());

    r = runPrepared(words("--sim dbu200@1 --json run 1 select 3 --yes"),
                    [](CliContext& c) { control(c, 1, "set 0x100D 2"); });
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_TRUE(o.value(QStringLiteral("sent")).toBool());
    EXPECT_EQ(o.value(QStringLiteral("state"))
                  .toObject()
                  .value(QStringLiteral("values"))
                  .toObject()
                  .value(QStringLiteral("Select running data"))
                  .toString(),
              QStringLiteral("SPno3"));
}

TEST(DriveCommands, RunRefusesWrongCommandsAndValues)
{
    const struct
    {
        const char* line;
        int code;
    } cases[] = {
        {"--sim dbu200@1 run", ExitUsage},
        {"--sim dbu200@1 run 1", ExitUsage},
        {"--sim dbu200@1 run 1 jump --yes", ExitUsage},
        {"--sim dbu200@1 run 1 select --yes", ExitUsage},
        {"--sim dbu200@1 run 1,2 start --yes", ExitUsage},
        {"--sim dbu200@1 run 1 select 9 --yes", ExitInvalid},
        {"--sim dcpid@7 run 7 start --yes", ExitUsage},
        {"--sim dcpid@7 run 7 speed 500 --yes", ExitInvalid},
        {"--sim dbu200@1 --timeout 50 run 4 start --yes", ExitCommunication},
    };
    for (const auto& c : cases) {
        const CliRun r = runCli(words(c.line));
        EXPECT_EQ(r.code, c.code) << c.line << ": " << qPrintable(r.err);
        EXPECT_TRUE(r.err.contains(QStringLiteral("error:"))) << c.line;
    }
    const CliRun dc = runCli(words("--sim dcpid@7 run 7 speed 50 --yes"));
    EXPECT_EQ(dc.code, ExitOk) << qPrintable(dc.err);
    EXPECT_TRUE(dc.out.contains(QStringLiteral("speed.command = 50 (0x0040, function 06)")))
        << qPrintable(dc.out);
}

TEST(DriveCommands, StopAllNeedsYesAndConfirmsEveryDrive)
{
    CliRun r = runCli(words("--sim dbu200@1,dcpid@7 stop-all"));
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("dbu: run.start = STOP (0) (0x2003, function 06)")))
        << qPrintable(r.err);
    EXPECT_TRUE(
        r.err.contains(QStringLiteral("dcpid: speed.command = 0.0 % (0x0040, function 06)")));

    r = runPrepared(words("--sim dbu200@1,dcpid@7 stop-all --yes"),
                    [](CliContext& c) { startDrive(c, 1); });
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.out + r.err);
    EXPECT_TRUE(
        QRegularExpression(QStringLiteral("\\n +1  dbu +stopped +0 r/min")).match(r.out).hasMatch())
        << qPrintable(r.out);
    EXPECT_TRUE(
        QRegularExpression(QStringLiteral("\\n +7  dcpid +stopped")).match(r.out).hasMatch());

    r = runCli(words("--sim dbu200@1 --timeout 50 stop-all --yes --ids 1,9"));
    EXPECT_EQ(r.code, ExitCommunication) << qPrintable(r.out);
    EXPECT_TRUE(QRegularExpression(QStringLiteral("\\n +9 + no answer")).match(r.out).hasMatch())
        << qPrintable(r.out);
    for (const char* line :
         {"--sim dbu200@1 stop-all --yes --ids x", "--sim dbu200@1 stop-all 1 --yes"})
        EXPECT_EQ(runCli(words(line)).code, ExitUsage) << line;
}

TEST(DriveCommands, StopAllReportsADriveThatDidNotStop)
{
    const CliRun r =
        runPrepared(words("--sim dbu200@1,dbu400@2 --json stop-all --yes"), [](CliContext& c) {
            startDrive(c, 1);
            startDrive(c, 2);
            control(c, 2, "ignore-stop on");
        });
    EXPECT_EQ(r.code, ExitMismatch) << qPrintable(r.out + r.err);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    // Asked afterwards (checked), but not every drive confirmed that it stopped.
    EXPECT_TRUE(o.value(QStringLiteral("checked")).toBool());
    EXPECT_FALSE(o.value(QStringLiteral("confirmed")).toBool(true));
    const QJsonArray drives = o.value(QStringLiteral("drives")).toArray();
    ASSERT_EQ(drives.size(), 2);
    EXPECT_EQ(drives[0].toObject().value(QStringLiteral("state")).toString(),
              QStringLiteral("stopped"));
    EXPECT_EQ(drives[1].toObject().value(QStringLiteral("state")).toString(),
              QStringLiteral("still-running"));
}
