#include "tests/faultmatrix/SelfTest.h"

#include "tests/faultmatrix/FaultJudge.h"
#include "tests/faultmatrix/MatrixSim.h"
#include "tests/faultmatrix/MatrixSteps.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace opentop::faultmatrix {

namespace {

Setting setting(int slave, const QString& name, quint16 value)
{
    Setting s;
    s.slave = slave;
    s.family = QStringLiteral("dbu");
    s.name = name;
    s.address = 0x1303;
    s.registers = {value};
    return s;
}

CliRun restoreRun(int code, const QString& status, const QString& outcome)
{
    const QJsonObject item{{QStringLiteral("parameter"), QStringLiteral("spno2.accel")},
                           {QStringLiteral("status"), status}};
    const QJsonObject drive{
        {QStringLiteral("slave"), 1},
        {QStringLiteral("outcome"), outcome},
        {QStringLiteral("reason"), code ? QStringLiteral("port error") : QString()},
        {QStringLiteral("items"), QJsonArray{item}}};
    CliRun run;
    run.code = code;
    run.out = QString::fromUtf8(
        QJsonDocument(QJsonObject{{QStringLiteral("drives"), QJsonArray{drive}}}).toJson());
    return run;
}

CliRun compareRun(const QStringList& parameters, quint16 shown)
{
    QJsonArray differences;
    for (const QString& p : parameters)
        differences << QJsonObject{{QStringLiteral("parameter"), p},
                                   {QStringLiteral("bRegisters"), QJsonArray{int(shown)}}};
    CliRun run;
    run.code = 0;
    run.out = QString::fromUtf8(
        QJsonDocument(QJsonObject{{QStringLiteral("differences"), differences}}).toJson());
    return run;
}

} // namespace

SelfTest::SelfTest(const MatrixOptions& options, QTextStream& log)
    : m_options(options)
    , m_log(log)
{
}

bool SelfTest::check(bool ok, const QString& what)
{
    m_log << (ok ? "  ok      " : "  FAILED  ") << what << '\n';
    m_failed += !ok;
    return ok;
}

void SelfTest::countingRules()
{
    const QVector<Setting> file{setting(1, QStringLiteral("spno2.accel"), 50)};
    Truth same;
    same.insert(MatrixSim::key(1, QStringLiteral("spno2.accel")), {50});
    Truth other;
    other.insert(MatrixSim::key(1, QStringLiteral("spno2.accel")), {7});

    FaultCounts c;
    CliRun backup;
    backup.code = 0;
    backup.out = QStringLiteral("wrote f: 1 drives\n");
    FaultJudge::backupDone(file, other, {1}, QStringLiteral("f"), backup, &c);
    check(c.backupDiffer == 1 && !c.clean(),
          QStringLiteral("a backed-up value the drive does not hold"));
    c = {};
    FaultJudge::backupDone(file, same, {1, 2}, QStringLiteral("f"), backup, &c);
    check(c.unreported >= 1, QStringLiteral("a backup that exited 0 without an asked drive"));
    c = {};
    FaultJudge::backupDone(file, same, {1}, QStringLiteral("f"), backup, &c);
    check(c.clean(), QStringLiteral("a correct backup counts nothing"));

    c = {};
    FaultJudge::restore(file, other,
                        restoreRun(0, QStringLiteral("verified"), QStringLiteral("done")), &c);
    check(c.notVerified == 1 && c.unreported == 1,
          QStringLiteral("a write reported verified that the drive does not hold"));
    c = {};
    FaultJudge::restore(file, other,
                        restoreRun(0, QStringLiteral("failed"), QStringLiteral("done")), &c);
    check(c.unreported >= 1, QStringLiteral("a failed write with exit 0"));
    c = {};
    FaultJudge::restore(
        file, other, restoreRun(1, QStringLiteral("failed"), QStringLiteral("communication")), &c);
    check(c.clean() && c.gaveUp == 1,
          QStringLiteral("a failed write, named, exit 1: gave up, not a fault"));
    c = {};
    CliRun silent = restoreRun(1, QStringLiteral("failed"), QStringLiteral("communication"));
    silent.out = QStringLiteral("{\"drives\":[{\"slave\":2,\"outcome\":\"done\"}]}");
    FaultJudge::restore(file, other, silent, &c);
    check(c.unreported >= 1, QStringLiteral("a wrong setting the report does not name"));
    c = {};
    FaultJudge::restore(file, same,
                        restoreRun(0, QStringLiteral("verified"), QStringLiteral("done")), &c);
    check(c.clean() && c.gaveUp == 0, QStringLiteral("a correct restore counts nothing"));
    c = {};
    FaultJudge::finalState(file, other, &c);
    check(c.wrongAfterRestore == 1, QStringLiteral("a drive left unequal to the backup"));

    c = {};
    FaultJudge::compare(file, same, 1, compareRun({QStringLiteral("spno2.accel")}, 50), &c);
    check(c.falseDifferences == 1,
          QStringLiteral("a difference compare shows that does not exist"));
    c = {};
    FaultJudge::compare(file, other, 1, compareRun({}, 0), &c);
    check(c.unreported == 1, QStringLiteral("a difference compare does not show"));
    c = {};
    FaultJudge::compare(file, other, 1, compareRun({QStringLiteral("spno2.accel")}, 7), &c);
    check(c.clean(), QStringLiteral("a real difference shown counts nothing"));
}

int SelfTest::run()
{
    m_log << "counting rules on made-up reports:\n";
    countingRules();
    m_log << "a short run with a drive changed behind the tool's back:\n";
    MatrixOptions sabotaged = m_options;
    sabotaged.sabotage = true;
    MatrixSteps steps(sabotaged, sabotaged.seeds.first(), m_log);
    const FaultCounts c = steps.runSeed();
    check(c.wrongAfterRestore >= 1 && !c.clean(),
          QStringLiteral("the sabotaged run is not clean (%1 wrong at the end)")
              .arg(c.wrongAfterRestore));
    m_log << (m_failed ? QStringLiteral("self-test FAILED: %1 planted fault(s) not counted\n")
                             .arg(m_failed)
                       : QStringLiteral("self-test passed: every planted fault was counted\n"));
    m_log.flush();
    return m_failed ? 1 : 0;
}

} // namespace opentop::faultmatrix
