#pragma once

#include <QString>
#include <QVector>
#include <optional>

namespace opentop::faultmatrix {

// opentop-faultmatrix's command line.
struct MatrixOptions
{
    QVector<int> seeds{1, 2, 3, 4, 5};
    int drives = 32;
    QString faults = QStringLiteral("drop=0.05,crc=0.02,late=0.02,busy=0.01");
    bool vanish = false;   // also pull the port out mid-backup and mid-restore
    bool selfTest = false; // prove the counting fails on an unreported fault
    bool sabotage = false; // corrupt a drive behind the tool's back: the run must fail
    int attempts = 4;      // runs of an operation that gave up before the seed is abandoned
    QString binDir;        // where opentop-sim and opentop-cli are
    bool verbose = false;
    QString traceDir; // --trace-dir: every opentop-cli run with --trace, its stderr kept here
    int baud = 19200; // the line's rate, for opentop-sim --wire-timing and opentop-cli
    // --late-sweep: every seed at each rate and each late-reply delay (ms), only late faults.
    QVector<int> lateSweepMs;
    QVector<int> sweepBauds{9600, 19200, 115200};
    double lateRate = 0.10;

    // parseSeeds' syntax for any list of numbers ("50,450,2000", "1-3").
    static std::optional<QVector<int>> parseList(const QString& text);
    static std::optional<MatrixOptions> parse(const QStringList& arguments, QString* error);
    static QString usage();
    // "dbu200@1,dbu200@2,dbu400@3,...": a mix of DBU200, DBU400 and DC controllers.
    static QString deviceSpec(int drives);
    // "1=dbu200,3=dbu400,...": the DBU variants, which the drives do not report.
    static QString variantList(int drives);
    static QString typeOf(int slave);
};

} // namespace opentop::faultmatrix
